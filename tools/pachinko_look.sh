#!/usr/bin/env bash
# Plays one pachinko board in a real window under Xvfb, driven by xdotool as a player would
# (Enter on the instructions starts the game, Shift held streams balls from the handle, Space charges one
# shot), and saves screenshots of the whole screen to build/look/<board>_<size>_<n>.png.
# A scratch user folder keeps the player's own settings and best results out of it.
#   tools/pachinko_look.sh hanami 720x1280     XVFB_NUM=63: the first X display number tried
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
BOARD=${1:?board name, e.g. hanami}
SIZE=${2:-1280x720}
OUT=build/look
mkdir -p "$OUT"
# shellcheck source=tools/look_board.sh
. tools/look_board.sh
look_board_setup pachinko "$BOARD"
WIDTH=${SIZE%x*}
HEIGHT=${SIZE#*x}
xvfb-run -a -n "${XVFB_NUM:-99}" -s "-screen 0 ${SIZE}x24" bash -c '
	timeout -s INT -k 5 40 tools/godot.sh --rendering-driver opengl3 --resolution '"$SIZE"' --position 0,0 --path . \
		res://scenes/pachinko/pachinko_game.tscn >"'"$OUT"'/'"$BOARD"'_'"$SIZE"'.log" 2>&1 &
	game=$!
	sleep 18
	shot() { import -window root "'"$OUT"'/'"$BOARD"'_'"$SIZE"'_$1.png"; }
	shot 0
	xdotool key Return
	sleep 0.5
	xdotool keydown shift
	sleep 5
	shot 1
	xdotool keyup shift keydown space
	sleep 0.8
	xdotool keyup space
	sleep 4
	shot 2
	wait $game || true
'
ls "$OUT"/"$BOARD"_"$SIZE"_*.png
