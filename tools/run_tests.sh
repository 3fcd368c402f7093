#!/usr/bin/env bash
# The whole test run: lint, every GUT test headless (JUnit XML in build/), the headless
# editor smoke check, the same GUT suites on Godot's release template (tools/release_tests.sh;
# its tests count in the totals), the windowed game under Xvfb (tools/play_check.sh; skipped,
# and said so, where Xvfb cannot be had), the release launcher's tests and, where this
# machine can, make release + the release check in a clean Debian 12 root and the scripted
# two-session check on the release folder (tools/release/test_hook.sh).
# Ends with one plain line "N passed, N failed"; exits non-zero when anything failed or no
# test ran.
set -uo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
mkdir -p build
XML=build/test-results.xml
LOG=build/test-output.log
rm -f "$XML"

extra_failed=0
echo "== lint"
tools/lint.sh || extra_failed=$((extra_failed + 1))

echo "== GDScript warnings (every script loaded with -d; physics/world only noted)"
tools/warnings_check.sh || extra_failed=$((extra_failed + 1))

echo "== GUT (tests/unit, tests/integration)"
# A user folder of its own, as the release template's run has (tools/release_tests.sh): the
# player's settings and saves on this machine (a frame counter left on, a board style picked
# while playing) must not change what the tests see, and the tests must not touch them.
gut_home=$(mktemp -d)
XDG_DATA_HOME=$gut_home tools/godot.sh --headless --path . -s addons/gut/gut_cmdln.gd \
	-gdir=res://tests/unit,res://tests/integration -ginclude_subdirs -gprefix=test_ \
	-gsuffix=.gd -gjunit_xml_file="res://$XML" -glog=1 -gexit 2>&1 | tee "$LOG"
gut_status=${PIPESTATUS[0]}
rm -rf "$gut_home"

# Godot prints script errors on stderr without failing GUT: count them as failures.
script_errors=$(grep -cE '^(SCRIPT ERROR|Parse Error|ERROR: .*(Parse|parse|script))' "$LOG" || true)
if [ "$script_errors" -gt 0 ]; then
	echo "test run printed $script_errors script error(s):"
	grep -E -A2 '^(SCRIPT ERROR|Parse Error|ERROR: .*(Parse|parse|script))' "$LOG" | head -40
	extra_failed=$((extra_failed + 1))
fi

echo "== GUT again on Godot's release template (tools/release_tests.sh: what players run)"
release_tests_status=77
setup_log=$(mktemp)
if tools/setup.sh export >"$setup_log" 2>&1; then
	tools/release_tests.sh
	release_tests_status=$?
	[ "$release_tests_status" = 0 ] || extra_failed=$((extra_failed + 1))
else
	echo "release tests: SKIPPED: no release export template ($(grep -v '^$' "$setup_log" | tail -n 1))"
fi
rm -f "$setup_log"

echo "== editor smoke check (plugin enabled, headless)"
tools/editor_smoke.sh || extra_failed=$((extra_failed + 1))

echo "== editor self-check (the board tool inside the headless editor)"
tools/editor_self_check.sh || extra_failed=$((extra_failed + 1))

echo "== play check (the game window under Xvfb)"
tools/play_check.sh
play_status=$?
if [ "$play_status" -ne 0 ] && [ "$play_status" -ne 77 ]; then
	extra_failed=$((extra_failed + 1))
fi

echo "== release (the launcher's tests; make release + the release check where it can run)"
tools/release/test_hook.sh
release_status=$?
if [ "$release_status" -ne 0 ] && [ "$release_status" -ne 77 ]; then
	extra_failed=$((extra_failed + 1))
fi

read -r passed failed < <(python3 tools/junit_counts.py "$XML")
if [ "$release_tests_status" != 77 ] && [ -f build/release-tests.xml ]; then
	read -r release_passed release_failed < <(python3 tools/junit_counts.py build/release-tests.xml)
	passed=$((passed + release_passed))
	failed=$((failed + release_failed))
fi
failed=$((failed + extra_failed))
if [ "$gut_status" -ne 0 ] && [ "$failed" -eq 0 ]; then
	failed=1 # GUT failed without a readable report: never report green
fi
[ "$play_status" -ne 77 ] || echo "(the play check was SKIPPED: no Xvfb, see above)"
[ "$release_status" -ne 77 ] || echo "(the release check was SKIPPED, see above)"
[ "$release_tests_status" -ne 77 ] || echo "(the release-template test run was SKIPPED, see above)"
echo "$passed passed, $failed failed"
if [ "$passed" -eq 0 ] || [ "$failed" -ne 0 ]; then
	exit 1
fi
