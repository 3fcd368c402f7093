#!/usr/bin/env bash
# Plays one maze board in a real window under Xvfb, driven by xdotool as a player would
# (the joystick dragged with the mouse, then the arrow keys), and saves screenshots of the
# whole screen to build/look/<board>_<size>_<n>.png. A scratch user folder keeps the
# player's own settings and best times out of it.
#   tools/maze_look.sh garden 1280x720 [tutorial]   (tutorial: the tutorial's look setting)
#   XVFB_NUM=64 tools/maze_look.sh ...   (the first X display number tried; 99 by default)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
BOARD=${1:?board name, e.g. garden}
SIZE=${2:-1280x720}
OUT=build/look
mkdir -p "$OUT"
# shellcheck source=tools/look_board.sh
. tools/look_board.sh
look_board_setup maze "$BOARD"
LOOK=${3:-}
if [ "$LOOK" = tutorial ]; then
	printf '[meta]\nversion=1\n[display]\nmaze_tutorial_look=true\n' >"$USERDIR/settings.cfg"
fi
xvfb-run -a -n "${XVFB_NUM:-99}" -s "-screen 0 ${SIZE}x24" bash -c '
	timeout -s INT -k 5 32 tools/godot.sh --rendering-driver opengl3 --resolution '"$SIZE"' --position 0,0 --path . \
		res://scenes/maze/maze_game.tscn >"'"$OUT"'/'"$BOARD"'_'"$SIZE"'.log" 2>&1 &
	game=$!
	sleep 18
	shot() { import -window root "'"$OUT"'/'"$BOARD"'_'"$SIZE$LOOK"'_$1.png"; }
	shot 0
	xdotool key Right
	xdotool keydown Right keydown Down
	sleep 2.5
	shot 1
	xdotool keyup Right keyup Down keydown Left
	sleep 2.5
	shot 2
	xdotool keyup Left
	wait $game || true
'
ls "$OUT"/"$BOARD"_"$SIZE$LOOK"_*.png
