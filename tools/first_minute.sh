#!/usr/bin/env bash
# Times a new player's first minute (tools/first_minute.py): the game launched in a real
# window under Xvfb with an empty user folder (a new player: default settings, nothing
# played), driven with xdotool from launch to the first shot. Prints the seconds of each
# step; screenshots go to build/look/first_minute_*.png.
#   tools/first_minute.sh             SIZE=1280x720 unless set; XVFB_NUM=77 the first display tried
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
SIZE=${SIZE:-1280x720}
SCRATCH=$(mktemp -d)
trap 'rm -rf "$SCRATCH"' EXIT
export XDG_DATA_HOME="$SCRATCH"
xvfb-run -a -n "${XVFB_NUM:-77}" -s "-screen 0 ${SIZE}x24" python3 tools/first_minute.py
