#!/usr/bin/env bash
# gdlint and gdformat --check over the project's own GDScript (never addons/gut).
#   tools/lint.sh          check only (make lint, make test)
#   tools/lint.sh --fix    reformat in place (make format)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
GDLINT=$(sed -n 's/^GDLINT=//p' build/tools.env)
GDFORMAT=$(sed -n 's/^GDFORMAT=//p' build/tools.env)
mapfile -t files < <(git ls-files -co --exclude-standard '*.gd' | grep -v '^addons/gut/' | sort)
if [ ${#files[@]} -eq 0 ]; then
	echo "lint: no GDScript files yet"
	exit 0
fi
if [ "${1:-}" = --fix ]; then
	"$GDFORMAT" "${files[@]}"
	exit 0
fi
status=0
"$GDLINT" "${files[@]}" || status=1
"$GDFORMAT" --check "${files[@]}" || status=1
if [ $status -ne 0 ]; then
	echo "lint: problems above (make format fixes the formatting ones)" >&2
fi
exit $status
