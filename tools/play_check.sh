#!/usr/bin/env bash
# The windowed game under Xvfb, as `make play` starts it: it must still be running after
# PLAY_SECONDS (5 unless set), print no crash, script error or library error, and render with
# the GL stack tools/godot.sh promises (the prefix's own Mesa when the setup's Godot runs).
# A child process that inherited the private library path shows up as "symbol lookup error".
# Prints the WARNING and ERROR lines the game printed meanwhile (reported, not failed).
# Exit status: 0 passed, 1 failed, 77 skipped (no Xvfb here: says so, never silently).
set -uo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
SECONDS_TO_RUN=${PLAY_SECONDS:-5}
LOG=build/play-check.log
mkdir -p build

if ! command -v xvfb-run >/dev/null 2>&1; then
	echo "play check SKIPPED: xvfb-run is not installed, so the game window cannot be opened"
	echo "  here. As root, 'make test' installs it; otherwise: sudo apt-get install xvfb"
	exit 77
fi

# timeout sends SIGINT after the wait (Godot quits cleanly on it) and reports 124 when it had
# to: so 124 means the game was still running. The outer timeout guards against a hang.
timeout 120 xvfb-run -a -s "-screen 0 1280x720x24" \
	timeout -s INT -k 10 "$SECONDS_TO_RUN" tools/godot.sh --path . >"$LOG" 2>&1
status=$?

failures=()
if [ $status -ne 124 ]; then
	failures+=("the game did not last ${SECONDS_TO_RUN} s under Xvfb (exit status $status)")
fi
# crashes, script errors, and children or libraries that the private prefix broke
BROKEN='handle_crash|Program crashed|SCRIPT ERROR|Parse Error|symbol lookup error'
BROKEN+='|error while loading shared libraries|Segmentation fault'
broken=$(grep -E "$BROKEN" "$LOG" | head -n 20 || true)
if [ -n "$broken" ]; then
	failures+=("it printed a crash or an error:")
	mapfile -t -O ${#failures[@]} failures <<<"$broken"
fi
renderer=$(grep -m 1 '^OpenGL API' "$LOG" || true)
if [ -z "$renderer" ]; then
	failures+=("it printed no 'OpenGL API' line: no GL context was made")
fi
env_file=build/tools.env
godot=$(sed -n 's/^GODOT=//p' "$env_file")
prefix=$(sed -n 's/^GODOT_PREFIX=//p' "$env_file")
if [ "$godot" = "$prefix/godot" ]; then
	# the prefix's Mesa names its one big library after its version: libgallium-26.2.6-1.so
	gallium=$(find "$prefix/root/usr/lib/x86_64-linux-gnu" -maxdepth 1 \
		-name 'libgallium-*.so' -printf '%f\n' | head -n 1)
	mesa=${gallium#libgallium-}
	mesa=${mesa%.so}
	if [ -z "$mesa" ]; then
		failures+=("the prefix has no Mesa (no libgallium-*.so): run 'make setup'")
	elif [ -n "$renderer" ] && [[ $renderer != *"Mesa $mesa "* ]]; then
		failures+=("the game did not use the prefix's Mesa $mesa: $renderer")
	fi
fi

echo "play check: ${renderer:-no renderer line}"
warnings=$(grep -E -A1 '^(WARNING|ERROR):' "$LOG" | grep -v '^--$' || true)
if [ -n "$warnings" ]; then
	echo "play check: the game printed these WARNING/ERROR lines in ${SECONDS_TO_RUN} s:"
	echo "$warnings" | sed 's/^/  /'
fi
if [ ${#failures[@]} -gt 0 ]; then
	echo "play check FAILED (log: $LOG):"
	printf '  %s\n' "${failures[@]}"
	exit 1
fi
echo "play check: ok (the game ran ${SECONDS_TO_RUN} s in a window)"
