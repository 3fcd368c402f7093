#!/usr/bin/env bash
# Renders the main screens under Xvfb to build/shots/*.png (make shots runs setup first):
# menus and pachinko (tools/shots/shot_runner.gd), the maze's own driver
# (tools/shots/maze_shots.tscn), then the board editor in use (tools/editor_shots.sh).
#   SHOTS_ONLY=menu tools/shots.sh    only the runner's shots whose names start with "menu"
#   SIZE=1920x1080 tools/shots.sh     another window size
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
SIZE=${SIZE:-1280x720}
mkdir -p build/shots
status=0
run_picture() {
	GODOT_PICTURES=1 timeout 300 xvfb-run -a -s "-screen 0 ${SIZE}x24" tools/godot.sh \
		--rendering-driver opengl3 --resolution "$SIZE" --path . "$@"
}
run_picture -s res://tools/shots/shot_runner.gd || status=1
if [ -z "${SHOTS_ONLY:-}" ] || [ "${SHOTS_ONLY}" = maze ]; then
	run_picture res://tools/shots/maze_shots.tscn || status=1
fi
if [ -z "${SHOTS_ONLY:-}" ] || [ "${SHOTS_ONLY}" = editor ]; then
	tools/editor_shots.sh || status=1
fi
ls -1 build/shots/*.png
exit $status
