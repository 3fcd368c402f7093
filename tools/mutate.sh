#!/usr/bin/env bash
# Mutation testing of the rule files (make mutate; not part of make test: it is slow).
#   tools/mutate.sh                          every file in tools/mutate/targets.txt
#   tools/mutate.sh scripts/app/medals.gd    one of them (make mutate FILE=...)
#   MUTATE_FROM=<git ref> tools/mutate.sh    mutate that commit's code with that commit's
#                                            tests (a "before" score); the lists stay ours
#
# gdmutant (PyPI, pinned below) changes one operator, constant or statement of a rule file
# at a time and runs the test files the list names for it; a change no test notices is a
# survivor. It is installed into a venv in the setup's cache (~/.cache/board-studio/), on a
# Python 3.12 or newer: the host's python3 when it is new enough, else one pyenv has (or
# installs). Each file runs in a throwaway copy of the project that holds only its own test
# files, so the checkout is never touched (gdmutant edits the file it mutates in place) and
# the tests you are writing meanwhile do not change the run.
#
# Survivors listed in tools/mutate/equivalents.txt (no behaviour can tell them from the
# original, each with its reason) are not counted. Writes build/mutate/<file>.json
# (gdmutant's report), .log, and build/mutate/table.md: file, mutants, killed, score and
# every survivor with its line.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
CACHE=${BOARD_STUDIO_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/board-studio}
GDMUTANT_VERSION=0.1.4
VENV=$CACHE/gdmutant-$GDMUTANT_VERSION
TARGETS=$ROOT/tools/mutate/targets.txt
EQUIVALENTS=$ROOT/tools/mutate/equivalents.txt
FROM=${MUTATE_FROM:-}
OUT=$ROOT/build/mutate${FROM:+/from-$FROM}

say() { printf 'mutate: %s\n' "$*" >&2; }
die() { printf '\nmutate failed: %s\n\n' "$*" >&2; exit 1; }

python_ok() { # python -> true when it runs and is 3.12 or newer
	"$1" -c 'import sys; sys.exit(0 if sys.version_info >= (3, 12) else 1)' >/dev/null 2>&1
}

find_python() {
	local candidate root
	for candidate in "${MUTATE_PYTHON:-}" python3 python3.14 python3.13 python3.12; do
		[ -n "$candidate" ] && command -v "$candidate" >/dev/null 2>&1 && python_ok "$candidate" &&
			{ command -v "$candidate"; return 0; }
	done
	local pyenv
	pyenv=$(command -v pyenv || true)
	[ -n "$pyenv" ] || [ ! -x "${PYENV_ROOT:-$HOME/.pyenv}/bin/pyenv" ] ||
		pyenv=${PYENV_ROOT:-$HOME/.pyenv}/bin/pyenv
	[ -n "$pyenv" ] || return 1
	root=$("$pyenv" root)
	for candidate in $(ls -d "$root"/versions/3.* 2>/dev/null | sort -Vr); do
		python_ok "$candidate/bin/python3" && { echo "$candidate/bin/python3"; return 0; }
	done
	say "no Python 3.12+ yet: pyenv installs one (it builds from source, a few minutes)"
	"$pyenv" install -s 3.12 >&2 || return 1
	for candidate in $(ls -d "$root"/versions/3.1[2-9]* 2>/dev/null | sort -Vr); do
		python_ok "$candidate/bin/python3" && { echo "$candidate/bin/python3"; return 0; }
	done
	return 1
}

install_gdmutant() {
	# the marker is written last: a half-made venv is never trusted
	[ -f "$VENV/.complete" ] && return 0
	local python
	python=$(find_python) || die "gdmutant needs Python 3.12 or newer, and this machine has none \
and no pyenv to build one. Install pyenv (its pyenv-installer script, then 'pyenv install 3.12') \
or set MUTATE_PYTHON to a python3.12+, and run 'make mutate' again."
	say "installing gdmutant $GDMUTANT_VERSION into $VENV (with $python)"
	rm -rf "$VENV"
	"$python" -m venv "$VENV" || die "$python -m venv failed"
	"$VENV/bin/pip" install -q "gdmutant==$GDMUTANT_VERSION" >/dev/null ||
		{ rm -rf "$VENV"; die "pip could not install gdmutant==$GDMUTANT_VERSION from PyPI."; }
	touch "$VENV/.complete"
}

tools/setup.sh >/dev/null
install_gdmutant
PY=$VENV/bin/python
HELPER=$ROOT/tools/mutate/mutate_lists.py

# Which lines of the list run: all, or those naming the files given.
mapfile -t lines < <("$PY" "$HELPER" targets "$TARGETS" "$@")
[ ${#lines[@]} -gt 0 ] || die "no rule file of tools/mutate/targets.txt matches: $*"

mkdir -p "$OUT"
WORK=$(mktemp -d "${TMPDIR:-/tmp}/board-studio-mutate.XXXXXX")
trap 'rm -rf "$WORK"' EXIT

# The project once, imported; each file then runs in its own copy of it.
BASE=$WORK/base
mkdir -p "$BASE"
if [ -n "$FROM" ]; then
	git rev-parse --verify -q "$FROM^{commit}" >/dev/null || die "MUTATE_FROM: no commit '$FROM'"
	say "mutating the code and tests of $FROM ($(git rev-parse --short "$FROM"))"
	git archive "$FROM" | tar -x -C "$BASE"
else
	git ls-files -co --exclude-standard -z | tar --null -T - -cf - | tar -xf - -C "$BASE"
fi
cp -a addons/gut "$BASE/addons/"
[ -d .godot ] && cp -a .godot "$BASE/"
tools/godot.sh --headless --path "$BASE" --import >/dev/null 2>&1 || true

reports=()
for line in "${lines[@]}"; do
	IFS='|' read -r file functions tests <<<"$line"
	name=$(basename "$file" .gd)
	copy=$WORK/$name
	cp -a "$BASE" "$copy"
	[ -f "$copy/$file" ] || { say "$file: not in this tree, skipped"; continue; }
	# only this file's tests, and only the functions in scope mutated
	kept=$("$PY" "$HELPER" prepare "$copy" "$file" "$functions" $tests)
	if [ -z "$kept" ]; then
		say "$file: none of its test files exist here ($tests), skipped"
		continue
	fi
	say "$file${functions:+ [$functions]}: tests $kept"
	rm -f "$OUT/$name.json"
	status=0
	(cd "$copy" && "$VENV/bin/gdmutant" run "$file" --project . --runner gut \
		--tests res://tests/unit,res://tests/integration --godot "$ROOT/tools/godot.sh" \
		--no-require-clean --progress plain --json "$OUT/$name.json") >"$OUT/$name.log" 2>&1 ||
		status=$?
	if [ ! -s "$OUT/$name.json" ]; then
		tail -20 "$OUT/$name.log" >&2
		die "gdmutant wrote no report for $file (exit $status); its output: $OUT/$name.log"
	fi
	printf '%s\t%s\n' "$file" "$functions" >"$OUT/$name.scope"
	reports+=("$OUT/$name.json")
	rm -rf "$copy"
done

[ ${#reports[@]} -gt 0 ] || die "nothing ran"
"$PY" "$HELPER" table "$EQUIVALENTS" "${reports[@]}"
# table.md: every file with a report here, this run's and earlier ones', in the list's order
mapfile -t all < <("$PY" "$HELPER" reports "$TARGETS" "$OUT")
"$PY" "$HELPER" table "$EQUIVALENTS" "${all[@]}" >"$OUT/table.md"
say "table of every file run so far: ${OUT#"$ROOT"/}/table.md"
