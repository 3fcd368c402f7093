#!/usr/bin/env bash
# Runs the exported game (build/export/, from make export) headless with both autoplays and
# checks that each prints one JSON line with "ok": true for the right game.
set -uo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
BINARY=build/export/board_studio.x86_64
if [ ! -x "$BINARY" ]; then
	echo "export-check: $BINARY is missing; run 'make export' first." >&2
	exit 1
fi
failed=0
for game in pachinko maze; do
	out=$(timeout 300 "$BINARY" --headless -- --autoplay="$game" --seconds=30 --seed=1 2>/dev/null)
	status=$?
	line=$(printf '%s\n' "$out" | grep -E '^\{' | tail -n 1)
	if ! verdict=$(printf '%s' "$line" | python3 -c '
import json, sys
game = sys.argv[1]
try:
    report = json.loads(sys.stdin.read())
except ValueError as error:
    sys.exit("no JSON line (%s)" % error)
if report.get("ok") is not True or report.get("game") != game:
    sys.exit("unexpected report: %s" % report)
print(" ".join("%s=%s" % (k, v) for k, v in report.items() if not isinstance(v, (dict, list))))
' "$game" 2>&1); then
		echo "export-check: $game FAILED (exit $status): $verdict"
		printf '%s\n' "$out" | tail -n 5
		failed=1
	elif [ "$status" -ne 0 ]; then
		echo "export-check: $game FAILED: exit status $status"
		failed=1
	else
		echo "export-check: $game ok: $verdict"
	fi
done
exit $failed
