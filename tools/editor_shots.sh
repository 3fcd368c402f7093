#!/usr/bin/env bash
# Screenshots of the board editor in use: opens the Godot editor under Xvfb on a board
# scene, selects its BoardNode, puts a tool to work (the plugin's shot hook, see
# tools/shots/editor_shot_hook.gd), saves the editor window as a PNG through
# tools/shots/shot_capture.gd (as the game's shots do) and quits.
#   tools/editor_shots.sh                       both shots into build/shots/
#   SIZE=1920x1080 tools/editor_shots.sh        another window size
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
SIZE=${SIZE:-1600x900}
PACHINKO_SCENE=${PACHINKO_SCENE:-res://scenes/boards/pachinko_tulips.tscn}
MAZE_SCENE=${MAZE_SCENE:-res://scenes/boards/maze_catacombs.tscn}
mkdir -p build/shots
# The editor reopens the scenes of its last session and saves them when a scene runs: start
# it with none open for each shot, and put the developer's session back afterwards.
LAYOUT=.godot/editor/editor_layout.cfg
saved_layout=$(mktemp)
[ -f "$LAYOUT" ] && cp "$LAYOUT" "$saved_layout"
forget_open_scenes() {
	[ ! -f "$LAYOUT" ] || sed -i '/^open_scenes=/d; /^current_scene=/d' "$LAYOUT"
}
restore_layout() {
	if [ -s "$saved_layout" ]; then cp "$saved_layout" "$LAYOUT"; else rm -f "$LAYOUT"; fi
	rm -f "$saved_layout"
}
# The shots edit a board and take the edit back, but the editor re-saves the board file in
# its own layout: put the committed boards back afterwards.
saved_levels=$(mktemp -d)
cp -a levels/. "$saved_levels"
restore_files() {
	local copy target
	while IFS= read -r -d '' copy; do
		target=levels/${copy#"$saved_levels"/}
		cmp -s "$copy" "$target" || cp "$copy" "$target"
	done < <(find "$saved_levels" -type f -print0)
	rm -rf "$saved_levels"
	restore_layout
}
trap restore_files EXIT

shoot() {
	local scene=$1 tool=$2 out=$3 log
	log=build/editor-shot-${tool}.log
	rm -f "build/shots/$out"
	forget_open_scenes
	GODOT_PICTURES=1 BOARD_EDITOR_HOOK=res://tools/shots/editor_shot_hook.gd \
		BOARD_EDITOR_SHOT="$scene;$tool;res://build/shots/$out" timeout 240 \
		xvfb-run -a -s "-screen 0 ${SIZE}x24" tools/godot.sh --editor \
		--rendering-driver opengl3 --resolution "$SIZE" --path . >"$log" 2>&1 || true
	if [ ! -f "build/shots/$out" ]; then
		echo "editor_shots: no build/shots/$out (log: $log)" >&2
		grep -E 'SCRIPT ERROR|Editor shot|editor shot' "$log" | head -20 >&2
		return 1
	fi
	echo "editor_shots: wrote build/shots/$out"
}

shoot "$PACHINKO_SCENE" curve editor_pachinko.png
shoot "$MAZE_SCENE" wall editor_maze.png
