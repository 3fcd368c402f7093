#!/usr/bin/env bash
# Checks the exported game (build/export/, from make export):
#  1. the .pck holds only the game: tools/pck_list.py fails on any test, tool, screenshot,
#     self-check, GUT, board editor, level scene or other editor-only path in it;
#  2. the game still runs without them: the exported binary starts its main menu, and each
#     game screen is loaded from that .pck alone (tools/godot.sh --main-pack) and played for
#     a moment with no error;
#  3. both headless autoplays print one JSON line with "ok": true for the right game.
set -uo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
BINARY=build/export/board_studio.x86_64
PACK=build/export/board_studio.pck
# Editor-only and development files; export_presets.cfg's exclude_filter leaves them out.
FORBIDDEN=(
	'tests/*' 'tools/*' 'build/*' 'docs/*' 'addons/gut/*' 'addons/board_editor/*'
	'*shots*' '*shot_capture*' '*shot_hook*' '*self_check*' 'scenes/boards/*' 'scenes/board_view/board_node.*'
)
# The screens the player can reach; each must load from the pack alone.
SCREENS=(
	scenes/menu/main_menu.tscn scenes/menu/level_select.tscn scenes/menu/settings_menu.tscn
	scenes/pachinko/pachinko_game.tscn scenes/maze/maze_game.tscn
)
if [ ! -x "$BINARY" ] || [ ! -f "$PACK" ]; then
	echo "export-check: $BINARY or $PACK is missing; run 'make export' first." >&2
	exit 1
fi
failed=0

forbid_args=()
for pattern in "${FORBIDDEN[@]}"; do forbid_args+=(--forbid "$pattern"); done
if python3 tools/pck_list.py "${forbid_args[@]}" "$PACK"; then
	echo "export-check: pack ok: nothing matches ${FORBIDDEN[*]}"
else
	echo "export-check: pack FAILED: it holds files the game must not ship (above)"
	failed=1
fi

# The release binary runs the main menu; engine teardown messages at quit are not ours.
log=$(mktemp)
if ! timeout 60 "$BINARY" --headless --quit-after 120 >"$log" 2>&1; then
	echo "export-check: main menu FAILED: the exported game exited with an error"
	tail -n 5 "$log"
	failed=1
elif grep -qE 'SCRIPT ERROR|Parse Error|Failed loading|Cannot open|Can.t open' "$log"; then
	echo "export-check: main menu FAILED:"
	grep -E 'SCRIPT ERROR|Parse Error|Failed loading|Cannot open|Can.t open' "$log" | head -5
	failed=1
else
	echo "export-check: main menu ok (exported binary, 120 frames)"
fi
# A release template refuses a scene on the command line, so the screens run on the
# setup's Godot with the exported pack as its only project (from a folder without one).
scratch=$(mktemp -d)
pack_path=$ROOT/$PACK
for screen in "${SCREENS[@]}"; do
	(cd "$scratch" && timeout 60 "$ROOT/tools/godot.sh" --headless --main-pack "$pack_path" \
		--quit-after 90 "res://$screen") >"$log" 2>&1
	status=$?
	if [ $status -ne 0 ] || grep -qE 'ERROR' "$log"; then
		echo "export-check: $screen FAILED from the pack (exit $status):"
		grep -E -A1 'ERROR' "$log" | head -8
		failed=1
	else
		echo "export-check: $screen ok from the pack (90 frames)"
	fi
done
rm -rf "$scratch" "$log"

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
