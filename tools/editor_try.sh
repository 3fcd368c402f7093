#!/usr/bin/env bash
# Opens the real Godot editor under Xvfb on a scratch copy of a board, with the board tool
# active, for trying the designer flow by hand or with xdotool (tests/editor/open_board.gd):
#   tools/editor_try.sh start pachinko|maze|new [DISPLAY_NUMBER]   prints the display
#   tools/editor_try.sh shot NAME        saves the screen to build/editor_try/NAME.png
#   tools/editor_try.sh stop
# The editor's session layout is put back on stop, as tools/editor_self_check.sh does.
set -uo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
DIR=build/editor_try
mkdir -p "$DIR"
LAYOUT=.godot/editor/editor_layout.cfg
case "${1:-}" in
start)
	kind=${2:-pachinko}
	num=${3:-77}
	[ -f "$LAYOUT" ] && cp "$LAYOUT" "$DIR/layout.saved" && sed -i '/^open_scenes=/d; /^current_scene=/d' "$LAYOUT"
	if [ "$kind" = new ]; then
		printf '[gd_scene load_steps=2 format=3]\n\n[ext_resource type="Script" path="res://scenes/board_view/board_node.gd" id="1_node"]\n\n[node name="Board" type="Node2D"]\nscript = ExtResource("1_node")\n' >"$DIR/$kind.tscn"
	else
		src=$([ "$kind" = maze ] && echo levels/maze/courtyards.board || echo levels/pachinko/tulips.board)
		cp "$src" "$DIR/$kind.board"
		printf '[gd_scene load_steps=3 format=3]\n\n[ext_resource type="Script" path="res://scenes/board_view/board_node.gd" id="1_node"]\n[ext_resource type="Resource" path="res://%s/%s.board" id="2_level"]\n\n[node name="Board" type="Node2D"]\nscript = ExtResource("1_node")\nlevel = ExtResource("2_level")\n' "$DIR" "$kind" >"$DIR/$kind.tscn"
	fi
	Xvfb ":$num" -screen 0 1600x900x24 >"$DIR/xvfb.log" 2>&1 &
	echo $! >"$DIR/xvfb.pid"
	sleep 1
	DISPLAY=":$num" BOARD_EDITOR_HOOK=res://tests/editor/open_board.gd \
		BOARD_EDITOR_OPEN="res://$DIR/$kind.tscn" \
		tools/godot.sh --editor --path . --rendering-driver opengl3 >"$DIR/editor.log" 2>&1 &
	echo $! >"$DIR/editor.pid"
	echo "$num" >"$DIR/display"
	for _ in $(seq 1 90); do
		grep -q "open_board: ready" "$DIR/editor.log" && break
		sleep 1
	done
	echo "DISPLAY=:$num"
	;;
shot)
	DISPLAY=":$(cat "$DIR/display")" xwd -root -silent | convert xwd:- "$DIR/${2:-screen}.png"
	echo "$DIR/${2:-screen}.png"
	;;
stop)
	[ -f "$DIR/editor.pid" ] && kill "$(cat "$DIR/editor.pid")" 2>/dev/null
	sleep 2
	[ -f "$DIR/xvfb.pid" ] && kill "$(cat "$DIR/xvfb.pid")" 2>/dev/null
	[ -f "$DIR/layout.saved" ] && cp "$DIR/layout.saved" "$LAYOUT" && rm -f "$DIR/layout.saved"
	rm -f "$DIR"/*.pid
	;;
*)
	sed -n 2,8p "$0"
	exit 2
	;;
esac
