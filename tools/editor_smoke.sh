#!/usr/bin/env bash
# Starts the Godot editor headless with the board tool enabled, lets it run a few hundred
# frames, quits, and fails on any script error it printed.
set -uo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
mkdir -p build
LOG=build/editor-smoke.log
timeout 180 tools/godot.sh --headless --editor --path . --quit-after 300 >"$LOG" 2>&1
status=$?
errors=$(grep -E 'SCRIPT ERROR|Parse Error|Failed to load script|Unable to load addon|Failed loading resource|ERROR: .*board_editor' "$LOG" | grep -v '^\s*$' || true)
if [ -n "$errors" ]; then
	echo "editor smoke check: the editor printed errors:"
	echo "$errors" | head -30
	exit 1
fi
if ! grep -q 'board_editor' <(grep -E 'enabled' project.godot); then
	echo "editor smoke check: the board_editor plugin is not enabled in project.godot"
	exit 1
fi
if [ $status -ne 0 ]; then
	echo "editor smoke check: the editor exited with status $status (log: $LOG)"
	exit 1
fi
echo "editor smoke check: ok"
