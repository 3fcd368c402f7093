#!/usr/bin/env bash
# Renders the main screens under Xvfb to build/shots/*.png (make shots runs setup first):
# the menus, pachinko and the maze (tools/shots/shot_runner.gd), then the board editor in
# use (tools/editor_shots.sh). Both save through tools/shots/shot_capture.gd.
#   SHOTS_ONLY=menu tools/shots.sh    only the shots whose names start with "menu"
#                                     (SHOTS_ONLY=editor: only the editor's two)
#   SIZE=1920x1080 tools/shots.sh     another window size for the game's shots
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
SIZE=${SIZE:-1280x720}
ONLY=${SHOTS_ONLY:-}
mkdir -p build/shots
status=0
if [ "$ONLY" != editor ]; then
	log=build/shots-game.log
	if ! GODOT_PICTURES=1 SHOTS_ONLY="$ONLY" timeout 300 xvfb-run -a -s "-screen 0 ${SIZE}x24" \
		tools/godot.sh --rendering-driver opengl3 --resolution "$SIZE" --path . \
		-s res://tools/shots/shot_runner.gd >"$log" 2>&1; then
		echo "shots: the game's shots failed (log: $log)" >&2
		grep -E 'shots:|SCRIPT ERROR|ERROR' "$log" | head -20 >&2
		status=1
	else
		grep -E '^shots:' "$log"
	fi
fi
if [ -z "$ONLY" ] || [ "$ONLY" = editor ]; then
	tools/editor_shots.sh || status=1
fi
exit $status
