#!/usr/bin/env bash
# A player's two sessions on the release folder, scripted with the keyboard under Xvfb on a
# small screen (900 x 700), with a fresh home folder:
#   menu -> Pachinko boards -> level select -> its first board -> pause -> back to menu ->
#   Tilt Maze -> level select -> back -> Settings (master volume one step down) -> back -> Quit,
# then the same again. Checks that
#   (1) the window fits the screen (never larger than 900 x 700),
#   (2) after each session the player's files are there, none moved aside (*.bad-*), and
#       the second start reports no problem with them (the release build once called every
#       file it had written damaged),
#   (3) the console and the game's log file hold no ERROR or WARNING line but those ALLOWED
#       below, with the reason, in those sessions and in each headless command (help,
#       autoplays, analyses, checks, a wrong flag).
# Screenshots of each step: build/session-check/<session>-<step>.png.
#   tools/release/session_check.sh [FOLDER]    default: build/release/board-studio-<version>
# Exit 0 passed, 1 failed, 77 skipped (no Xvfb or xdotool here).
set -uo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
cd "$ROOT" || exit 1
REPORT=build/session-check
folder=${1:-$(ls -d build/release/board-studio-*/ 2>/dev/null | head -n 1)}
folder=${folder%/}
[ -x "$folder/board-studio" ] || { echo "session check: no release folder (make release)"; exit 1; }
for tool in Xvfb xdotool xwd xwdtopnm pnmtopng; do
	command -v "$tool" >/dev/null || { echo "session check: SKIPPED: no $tool here"; exit 77; }
done
# Lines the console may hold, each with why it is not the game's fault:
#   V-Sync: Xvfb has no vertical sync to give, so Godot says it falls back.
ALLOWED='V-Sync|vsync'

rm -rf "$REPORT"
mkdir -p "$REPORT"
home=$(mktemp -d)
n=80
while [ -e "/tmp/.X11-unix/X$n" ] || [ -e "/tmp/.X$n-lock" ]; do n=$((n + 1)); done
Xvfb ":$n" -screen 0 900x700x24 -nolisten tcp -ac >/dev/null 2>&1 &
xvfb_pid=$!
cleanup() { kill "$xvfb_pid" 2>/dev/null; rm -rf "$home"; }
trap cleanup EXIT
for _ in $(seq 50); do [ -e "/tmp/.X11-unix/X$n" ] && break; sleep 0.1; done
export DISPLAY=":$n"
failed=0
fail() { echo "session check: FAILED: $*"; failed=1; }
ok() { echo "session check: ok: $*"; }
data="$home/.local/share/godot/app_userdata/Board Studio"

shoot() { # session step
	xwd -root 2>/dev/null | xwdtopnm 2>/dev/null | pnmtopng >"$REPORT/$1-$2.png" 2>/dev/null
}
keys() { # pause-after key... (to the game's window)
	local wait=$1
	shift
	xdotool windowfocus --sync "$window" 2>/dev/null
	for key in "$@"; do
		xdotool key "$key"
		sleep 0.4
	done
	sleep "$wait"
}

session() { # number
	local log=$REPORT/session-$1.log
	HOME=$home XDG_DATA_HOME=$home/.local/share XDG_CONFIG_HOME=$home/.config \
		BOARD_STUDIO_SOFTWARE_GL=1 "$folder/board-studio" >"$log" 2>&1 &
	local pid=$!
	window=
	for _ in $(seq 60); do
		window=$(xdotool search --onlyvisible --name "Board Studio" 2>/dev/null | head -n 1)
		[ -n "$window" ] && break
		sleep 0.5
	done
	[ -n "$window" ] || { fail "session $1: no window appeared"; kill "$pid"; return; }
	sleep 8
	shoot "$1" 1-menu
	local width= height=
	WIDTH= HEIGHT=
	for _ in $(seq 5); do
		eval "$(xdotool getwindowgeometry --shell "$window" 2>/dev/null | grep -E '^(WIDTH|HEIGHT)=[0-9]+$')"
		width=${WIDTH:-}
		height=${HEIGHT:-}
		[ -n "$width" ] && break
		sleep 1
	done
	if [ "${width:-9999}" -le 900 ] && [ "${height:-9999}" -le 700 ]; then
		ok "session $1: the window is ${width}x${height} on a 900x700 screen"
	else
		fail "session $1: the window is ${width:-?}x${height:-?}, larger than the 900x700 screen"
	fi
	keys 6 Down Return                   # Pachinko boards (under Play Pachinko): its list
	shoot "$1" 2-pachinko-boards
	keys 8 Return                        # its first board
	shoot "$1" 3-pachinko
	keys 2 Escape                        # the pause menu (or the rules card first)
	shoot "$1" 4-pause
	keys 4 Down Down Down Return         # Other boards, the last button: pachinko's list
	shoot "$1" 5-other-boards
	keys 4 Escape                        # back to the title screen, on Play Pachinko
	keys 6 Down Down Return              # Tilt Maze: its level select
	shoot "$1" 6-maze-boards
	keys 4 Escape                        # back to the title screen, on Tilt Maze
	keys 3 Down Return                   # Settings
	shoot "$1" 7-settings
	keys 2 Left Escape                   # master volume one step down, back (saves)
	shoot "$1" 8-after-settings
	keys 4 Down Return                   # Quit, below Settings
	for _ in $(seq 20); do kill -0 "$pid" 2>/dev/null || break; sleep 0.5; done
	if kill -0 "$pid" 2>/dev/null; then
		fail "session $1: Quit did not end the game (screens: $REPORT/$1-*.png)"
		kill "$pid"
	fi
	wait "$pid" 2>/dev/null
	local moved
	moved=$(ls "$data" 2>/dev/null | grep '\.bad-' || true)
	if [ -n "$moved" ]; then
		fail "session $1: player files were moved aside as damaged: $(echo $moved)"
	else
		ok "session $1: no player file moved aside ($(ls "$data" 2>/dev/null | grep -c 'cfg$') files)"
	fi
	local said
	said=$(grep -iE 'could not be (read|used)|damaged' "$log" | head -n 3)
	[ -z "$said" ] || fail "session $1: the game reported a problem with the player's files: $said"
	local noise
	noise=$(grep -E '^(ERROR|WARNING|SCRIPT ERROR)' "$log" | grep -vE "$ALLOWED" | head -n 5)
	local allowed
	allowed=$(grep -E '^(ERROR|WARNING)' "$log" | grep -cE "$ALLOWED")
	if [ -n "$noise" ]; then
		fail "session $1: the console holds ERROR/WARNING lines ($log): $noise"
	else
		ok "session $1: no ERROR or WARNING line on the console ($allowed allowed: V-Sync)"
	fi
	# the log file a player would send with a bug report: as quiet as the console (the
	# engine's own log once held two false errors each time a control left a container)
	local logged
	logged=$(cat "$data"/logs/*.log 2>/dev/null | grep -E '^(ERROR|WARNING|SCRIPT ERROR)' |
		grep -vE "$ALLOWED" | head -n 3)
	if [ ! -f "$data/logs/godot.log" ]; then
		fail "session $1: the game wrote no log file ($data/logs/godot.log)"
	elif [ -n "$logged" ]; then
		fail "session $1: the game's log file holds ERROR/WARNING lines: $logged"
	else
		ok "session $1: no ERROR or WARNING line in the log file ($(ls "$data/logs" | wc -l) logs)"
	fi
}

# every headless command a player or a script may run: a quiet console too
for args in "--help" "--autoplay=pachinko --seconds=3" "--autoplay=maze --seconds=3" \
	"--analyze=pachinko --shots=50" "--analyze=maze --runs=1" "--check-boards" "--optimise"; do
	# shellcheck disable=SC2086 # the flags are split on purpose
	noise=$(HOME=$home XDG_DATA_HOME=$home/.local/share XDG_CONFIG_HOME=$home/.config \
		"$folder/board-studio" --headless -- $args 2>&1 >/dev/null |
		grep -E '^(ERROR|WARNING|SCRIPT ERROR)' | head -n 3)
	if [ -n "$noise" ]; then
		fail "--headless -- $args printed: $noise"
	else
		ok "--headless -- $args: no ERROR or WARNING line"
	fi
done
rm -rf "$data"

session 1
[ -f "$data/settings.cfg" ] || fail "session 1 left no settings.cfg (the volume change was not saved)"
cp "$data/settings.cfg" "$REPORT/settings-after-1.cfg" 2>/dev/null
session 2
if [ -f "$data/settings.cfg" ] && grep -q '^master_volume=0\.9' "$data/settings.cfg"; then
	ok "the volume set in session 1 and lowered again in session 2 is kept (master_volume $(sed -n 's/^master_volume=//p' "$data/settings.cfg"))"
elif [ -f "$data/settings.cfg" ]; then
	ok "settings.cfg kept: master_volume $(sed -n 's/^master_volume=//p' "$data/settings.cfg")"
fi
[ "$failed" = 0 ] && echo "session check: passed (screens in $REPORT/)"
exit $failed
