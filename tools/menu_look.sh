#!/usr/bin/env bash
# Walks the menus in a real window under Xvfb, driven by xdotool as a player would (keys,
# then mouse clicks), and saves a screenshot after each step to build/look/menu_<size>_<n>.png:
# the title screen, the maze level select, a card's menu, the settings (scrolled), the
# pachinko level select (clicked) and a board's instructions (clicked). A scratch user
# folder keeps the player's own settings, boards and best times out of it.
#   tools/menu_look.sh 720x1280          XVFB_NUM=64: the first X display number tried
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
SIZE=${1:-1280x720}
OUT=build/look
mkdir -p "$OUT"
SCRATCH=$(mktemp -d)
trap 'rm -rf "$SCRATCH"' EXIT
export XDG_DATA_HOME="$SCRATCH"
W=${SIZE%x*}
H=${SIZE#*x}
xvfb-run -a -n "${XVFB_NUM:-99}" -s "-screen 0 ${SIZE}x24" bash -c '
	timeout -s INT -k 5 80 tools/godot.sh --rendering-driver opengl3 --resolution '"$SIZE"' \
		--position 0,0 --path . >"'"$OUT"'/menu_'"$SIZE"'.log" 2>&1 &
	game=$!
	sleep 10
	shot() { sleep 1.5; import -window root "'"$OUT"'/menu_'"$SIZE"'_$1.png"; }
	click() { xdotool mousemove "$1" "$2" click 1; }
	shot 0
	xdotool key Down Return
	sleep 3
	shot 1
	xdotool key Right Down
	shot 2
	xdotool key x
	shot 3
	xdotool key Escape
	sleep 1
	xdotool key Escape
	sleep 2
	# the title screen focuses the game seen last (Tilt Maze): Settings is one down
	xdotool key Down Return
	shot 4
	for i in $(seq 14); do xdotool key Down; done
	shot 5
	xdotool key Escape
	sleep 1
	xdotool key Up Up Return
	sleep 3
	shot 6
	click $(('"$W"' * 24 / 100)) $(('"$H"' * 22 / 100))
	sleep 4
	shot 7
	kill -INT $game 2>/dev/null || true
	wait $game || true
'
ls "$OUT"/menu_"$SIZE"_*.png
