#!/usr/bin/env bash
# Seconds from a click on a maze board to the board on the screen, and the longest time the
# loading ring stood still meanwhile (tools/shots/maze_open_time.gd), under Xvfb (software GL).
#   MAZE_OPEN_BOARD=classic tools/maze_open_time.sh      another board (first_roll unless set)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
SIZE=${SIZE:-1280x720}
mkdir -p build
log=build/maze_open_time.log
if ! timeout 300 xvfb-run -a -s "-screen 0 ${SIZE}x24" tools/godot.sh --rendering-driver opengl3 \
	--resolution "$SIZE" --path . -s res://tools/shots/maze_open_time.gd >"$log" 2>&1; then
	echo "maze_open_time: failed (log: $log)" >&2
	grep -E 'maze_open_time:|SCRIPT ERROR|ERROR' "$log" | head -20 >&2
	exit 1
fi
grep -E '^maze_open_time:' "$log"
