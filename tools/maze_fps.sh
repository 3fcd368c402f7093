#!/usr/bin/env bash
# The 3D maze's frame rate under Xvfb at 1280x720 (software GL), every render variant of
# tools/shots/maze_fps.gd measured side by side in one run, in frames per CPU second.
#   MAZE_FPS_ROUNDS=5 MAZE_FPS_FRAMES=60 tools/maze_fps.sh    longer, steadier
#   SIZE=1920x1080 tools/maze_fps.sh                          another window size
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
SIZE=${SIZE:-1280x720}
mkdir -p build
log=build/maze_fps.log
if ! timeout 600 xvfb-run -a -s "-screen 0 ${SIZE}x24" tools/godot.sh --rendering-driver opengl3 \
	--resolution "$SIZE" --path . -s res://tools/shots/maze_fps.gd >"$log" 2>&1; then
	echo "maze_fps: failed (log: $log)" >&2
	grep -E 'maze_fps:|SCRIPT ERROR|ERROR' "$log" | head -20 >&2
	exit 1
fi
grep -E '^maze_fps:' "$log"
