#!/usr/bin/env bash
# make test's release part: the tests of the launcher's error paths and of elf_paths.py
# always; then, when this machine can, make release, the release check
# (tools/release/check.sh) and two scripted sessions on the folder (session_check.sh). Prints SKIPPED with the reason for the part it cannot do.
# Exit 0 passed, 1 failed, 77 the release check skipped.
set -uo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
cd "$ROOT" || exit 1
skip() { echo "release check: SKIPPED: $*"; exit 77; }

status=0
tools/release/launcher_test.sh || status=1
tools/release/elf_paths_test.sh || status=1
[ "$status" = 0 ] || exit 1

GODOT=$(sed -n 's/^GODOT=//p' build/tools.env 2>/dev/null)
PREFIX=$(sed -n 's/^GODOT_PREFIX=//p' build/tools.env 2>/dev/null)
[ -n "$PREFIX" ] && [ "$GODOT" = "$PREFIX/godot" ] ||
	skip "the release is built from the setup's own Debian Godot, and GODOT points at another one ($GODOT)"
[ "$(id -u)" = 0 ] || skip "the release check enters a Debian 12 root (chroot), which needs root"
log=$(mktemp)
if ! tools/setup.sh export >"$log" 2>&1; then
	reason=$(grep -v '^$' "$log" | tail -n 1); rm -f "$log"
	skip "Debian's export templates could not be had: $reason"
fi
rm -f "$log"
started=$(date +%s)
tools/release/build.sh || { echo "release check: FAILED: make release failed (above)"; exit 1; }
echo "release check: the release was built in $(($(date +%s) - started)) s"
started=$(date +%s)
tools/release/check.sh
status=$?
echo "release check: the check took $(($(date +%s) - started)) s"
folder=$(ls -d build/release/board-studio-*/ | head -n 1)
tools/release/session_check.sh "$folder"
session_status=$?
[ "$session_status" = 0 ] || [ "$session_status" = 77 ] || status=1
exit $status
