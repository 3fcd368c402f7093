#!/usr/bin/env bash
# Every shipped maze board at rest and at full tilt at 1280x720, 900x700 and 720x1280, under
# Xvfb: build/look/boards/<board>_<size>_rest.png and _tilt.png (tools/shots/maze_board_shots.gd).
#   tools/maze_board_shots.sh [board,board...] [size ...]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
BOARDS=${1:-}
shift || true
SIZES=("$@")
[ ${#SIZES[@]} -gt 0 ] || SIZES=(1280x720 900x700 720x1280)
mkdir -p build/look/boards
for size in "${SIZES[@]}"; do
	args=()
	[ -z "$BOARDS" ] || args=(-- "--boards=$BOARDS")
	GODOT_PICTURES=1 timeout 600 xvfb-run -a -s "-screen 0 ${size}x24" \
		tools/godot.sh --rendering-driver opengl3 --resolution "$size" --path . \
		-s res://tools/shots/maze_board_shots.gd "${args[@]}" >"build/look/boards/shots_$size.log" 2>&1 ||
		{ echo "maze_board_shots: $size failed (build/look/boards/shots_$size.log)" >&2; exit 1; }
done
ls build/look/boards/*.png | wc -l
