#!/usr/bin/env bash
# GDScript warnings check: loads every script under scenes/, scripts/ and
# addons/board_editor with the debugger on (-d, as the editor's play-test does) through
# tools/load_all_scripts.gd and lists each warning with its file:line.
# Fails (exit 1) on any warning: each one is a Debugger entry on every play-test. project.godot
# is never touched: the loader turns warnings on for addons/board_editor at run time.
set -uo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
mkdir -p build
ERR=build/warnings-check.log

timeout 180 tools/godot.sh --headless -d --path . -s res://tools/load_all_scripts.gd \
	</dev/null >build/warnings-check.out 2>"$ERR"
status=$?
if [ "$status" -ne 0 ] || ! grep -q '^LOADED [0-9]' build/warnings-check.out; then
	echo "warnings check: the loader failed (exit $status):"
	grep -E 'LOADFAIL|ERROR' "$ERR" | head -20
	exit 1
fi

# Each warning is a "WARNING: text" line followed by "   at: ... (res://file:line)".
LIST=build/warnings-check.txt
awk '
	/^WARNING: / { msg = substr($0, 10); next }
	msg != "" {
		where = "unknown location"
		if (match($0, /\([^()]*:[0-9]+\)$/)) {
			where = substr($0, RSTART + 1, RLENGTH - 2)
		}
		sub(/^res:\/\//, "", where)
		print "warning: " where ": " msg
		msg = ""
	}
' "$ERR" | sort -t: -k1,2 -k3,3n >"$LIST"
failing=$(grep -c '^warning: ' "$LIST")
cat "$LIST"
loaded=$(sed -n 's/^LOADED //p' build/warnings-check.out)
echo "warnings check: $loaded scripts loaded, $failing warning(s)"
[ "$failing" -eq 0 ]
