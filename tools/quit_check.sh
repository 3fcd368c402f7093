#!/usr/bin/env bash
# Quits the game RUNS times (20 unless set) while the level select is still loading board
# files, every other time just after a file drop (an import running), each after a
# different number of frames (tools/quit_during_loading.gd). Fails when any run exits
# badly, prints a crash or destroys a thread that was still running.
# Exit status: 0 passed, 1 failed.
set -uo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
RUNS=${RUNS:-20}
mkdir -p build
LOG=build/quit-check.log
: >"$LOG"
BROKEN='handle_crash|Program crashed|SCRIPT ERROR|Segmentation fault|Aborted|out of bounds'
BROKEN+='|destroyed without its completion'
failed=0
for run in $(seq 1 "$RUNS"); do
	mode=""
	if [ $((run % 2)) -eq 0 ]; then mode="drop"; fi
	frames=$(((run + 1) / 2))
	out=$(timeout 60 tools/godot.sh --headless --path . -s res://tools/quit_during_loading.gd \
		-- "$frames" $mode 2>&1)
	status=$?
	echo "== run $run (frames $frames $mode): exit $status" >>"$LOG"
	echo "$out" >>"$LOG"
	broken=$(echo "$out" | grep -E "$BROKEN" | head -n 3)
	if [ $status -ne 0 ] || [ -n "$broken" ]; then
		echo "quit check: run $run (quit after $frames frames $mode) failed, exit $status"
		[ -n "$broken" ] && echo "$broken"
		failed=$((failed + 1))
	fi
done
if [ $failed -ne 0 ]; then
	echo "quit check FAILED: $failed of $RUNS runs (log: $LOG)"
	exit 1
fi
echo "quit check passed: $RUNS quits while loading, no crash (log: $LOG)"
