#!/usr/bin/env bash
# Checks the board editor inside the real (headless) Godot editor: an edit goes through the
# plugin into the edited scene's undo history, undo and redo work there, and saving the
# scene writes the board file, a board node without a board gets a new one (undoably),
# and play-test writes the request naming the board. Works on scratch copies in build/.
set -uo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
DIR=build/editor_self_check
mkdir -p "$DIR"
# The editor reopens the scenes of its last session and saves them when a scene runs: start
# it with none open, and put the developer's session back afterwards.
LAYOUT=.godot/editor/editor_layout.cfg
saved_layout=$(mktemp)
if [ -f "$LAYOUT" ]; then
	cp "$LAYOUT" "$saved_layout"
	sed -i '/^open_scenes=/d; /^current_scene=/d' "$LAYOUT"
fi
restore_layout() {
	if [ -s "$saved_layout" ]; then cp "$saved_layout" "$LAYOUT"; else rm -f "$LAYOUT"; fi
	rm -f "$saved_layout"
}
trap restore_layout EXIT
# Errors a headless editor prints on its own, with or without the board tool: the scene
# thumbnail on the dummy renderer, the play-tested game finding no display, and undoing the
# new board past the scene's save point (Godot's own history bookkeeping).
KNOWN_EDITOR_NOISE='Parameter "t" is null|X11 Display|Wayland|DisplayServer|Inconsistent redo history'
status=0
# ONLY_KIND=maze|pachinko|new runs one of the three checks (when chasing one failure).
for kind in ${ONLY_KIND:-maze pachinko new}; do
	log=$DIR/$kind.log
	if [ "$kind" = new ]; then
		# A BoardNode with no board: the check presses "New maze board" first.
		printf '[gd_scene load_steps=2 format=3]\n\n[ext_resource type="Script" path="res://scenes/board_view/board_node.gd" id="1_node"]\n\n[node name="Board" type="Node2D"]\nscript = ExtResource("1_node")\n' >"$DIR/$kind.tscn"
	else
	src=$([ "$kind" = maze ] && echo levels/maze/courtyards.board || echo levels/pachinko/tulips.board)
	cp "$src" "$DIR/$kind.board"
	cat >"$DIR/$kind.tscn" <<SCENE
[gd_scene load_steps=3 format=3]

[ext_resource type="Script" path="res://scenes/board_view/board_node.gd" id="1_node"]
[ext_resource type="Resource" path="res://$DIR/$kind.board" id="2_level"]

[node name="Board" type="Node2D"]
script = ExtResource("1_node")
level = ExtResource("2_level")
SCENE
	fi
	BOARD_EDITOR_SELF_CHECK_PLAY=$([ "$kind" = maze ] && echo 1 || echo 0) \
		BOARD_EDITOR_HOOK=res://tests/editor/self_check.gd \
		BOARD_EDITOR_SELF_CHECK="res://$DIR/$kind.tscn" \
		timeout 180 tools/godot.sh --headless --editor --path . >"$log" 2>&1
	# Any engine error while the check ran fails it too (dragging 624 pins once printed 57).
	errors=$(grep -E 'SCRIPT ERROR|^ERROR:' "$log" | grep -v -E "$KNOWN_EDITOR_NOISE" || true)
	if grep -q 'board editor self-check: ok' "$log" && [ -z "$errors" ]; then
		echo "editor self-check ($kind): ok"
	else
		echo "editor self-check ($kind): failed (log: $log)"
		grep -E 'self-check' "$log" | head -10
		echo "$errors" | head -10
		status=1
	fi
done
# The scratch boards would otherwise show up in the editor's FileSystem dock.
[ $status -eq 0 ] && rm -f "$DIR"/*.tscn "$DIR"/*.board
exit $status
