#!/usr/bin/env bash
# The unit and integration suites on what ships: Godot's release export template, with the
# game's own export settings (scripts as compressed binary tokens, the same filters) plus
# tests/ and GUT ("Tests" preset of export_presets.cfg). make test runs it after the editor
# build's GUT run; the release check runs the same pack inside its clean Debian 12 root.
#
#   tools/release_tests.sh            build the pack, run it here on build/export's binary
#   tools/release_tests.sh FILE...    the same with these test files only (tests/unit/x.gd)
#   tools/release_tests.sh --pack DIR build the pack into DIR only (tests.pck, fixtures.pck,
#                                     tests.list), for a run elsewhere (tools/release/check.sh)
#
# A test file that cannot run on the release template is left out with its reason, printed
# every run: the board tool's tests (addons/board_editor is editor-only and not in the game)
# and those listed in tests/release/not_on_release.txt. The developer tools (tools/*.gd) are
# in the test pack: some tests drive the game's code through them. JUnit XML: build/release-tests.xml.
# Exit 0 passed, 1 failed.
set -uo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT" || exit 1
GODOT=tools/godot.sh
SKIP_LIST=tests/release/not_on_release.txt
die() { echo "release tests: FAILED: $*"; exit 1; }

pack_only=
OUT=build/test-pack
if [ "${1:-}" = --pack ]; then
	[ -n "${2:-}" ] || die "--pack needs a folder"
	pack_only=1
	OUT=$2
	shift 2
fi
for file in "$@"; do
	[ -f "$file" ] || die "no test file $file"
done
mkdir -p "$OUT"

# the test files: every test_*.gd of the two suites, less those that cannot run there
list=$OUT/tests.list
: >"$list"
skipped=0
while IFS= read -r file; do
	reason=$(awk -v f="$file" -F ' *\\| *' '$1 == f { print $2 }' "$SKIP_LIST")
	if [ -z "$reason" ] && grep -q 'res://addons/board_editor/' "$file"; then
		reason="tests the board tool (addons/board_editor), which runs in the editor only"
	fi
	if [ -z "$reason" ]; then # a developer tool it loads may use the board tool
		for tool in $(grep -o 'res://tools/[A-Za-z0-9_/]*\.gd' "$file" | sort -u); do
			if grep -q 'res://addons/board_editor/' "${tool#res://}"; then
				reason="loads ${tool#res://}, which uses the board tool (editor only)"
				break
			fi
		done
	fi
	if [ -n "$reason" ]; then
		echo "release tests: not run on the release template: $file ($reason)"
		skipped=$((skipped + 1))
	else
		echo "res://$file" >>"$list"
	fi
done < <(if [ $# -gt 0 ]; then printf '%s\n' "$@"; else
	find tests/unit tests/integration -name 'test_*.gd' | sort; fi)
echo "release tests: $(wc -l <"$list") test files to run, $skipped left out (above)"

# the export re-saves project.godot in its own layout: put the committed text back after
saved_project=$(mktemp)
cp project.godot "$saved_project"
log=$(mktemp)
restore() {
	cmp -s "$saved_project" project.godot || cp "$saved_project" project.godot
	rm -f "$saved_project" "$log"
}
trap restore EXIT
timeout 600 "$GODOT" --headless --path . --export-pack "Tests" "$OUT/tests.pck" >"$log" 2>&1 ||
	{ cat "$log"; die "the test pack's export failed (above)"; }
if grep -qE 'SCRIPT ERROR|Parse Error|ERROR: .*[Ee]xport' "$log"; then
	grep -E -A2 'SCRIPT ERROR|Parse Error|ERROR: .*[Ee]xport' "$log" | head -30
	die "Godot reported errors while exporting the test pack (above)"
fi
"$GODOT" --headless --path . -s tools/fixture_pack.gd -- "$OUT/fixtures.pck" >"$log" 2>&1 ||
	{ cat "$log"; die "the fixture pack could not be made (above)"; }
if [ -n "$pack_only" ]; then
	echo "release tests: pack ready in $OUT"
	exit 0
fi

# the release template, patched to run on this machine (tools/export.sh), under the pack's
# name: a release template loads the pack named like itself and takes no --main-pack
[ -x build/export/board_studio.x86_64 ] || tools/export.sh >"$log" 2>&1 ||
	{ cat "$log"; die "the game's export failed (above)"; }
ln -f build/export/board_studio.x86_64 "$OUT/tests.x86_64"
home=$(mktemp -d)
xml=$ROOT/build/release-tests.xml
rm -f "$xml"
HOME=$home XDG_DATA_HOME=$home/.local/share XDG_CONFIG_HOME=$home/.config \
	timeout 1800 "$OUT/tests.x86_64" --headless \
	-gtest="$(paste -sd, "$list")" -gjunit_xml_file="$xml" -glog=1 -gexit \
	2>&1 | tee build/release-tests.log
status=${PIPESTATUS[0]}
rm -rf "$home"
read -r passed failed < <(python3 tools/junit_counts.py "$xml")
echo "release tests: $passed passed, $failed failed on the release template"
[ "$status" = 0 ] && [ "$failed" = 0 ] && [ "$passed" -gt 0 ]
