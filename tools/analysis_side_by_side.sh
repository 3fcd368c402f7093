#!/usr/bin/env bash
# The pachinko analysis's speed, this build against another checkout, side by side in one
# run: the two builds take turns (this, other, this, ...) ROUNDS times, so a busy moment on a
# shared machine costs both alike, and each build's best run (least wall time) is its figure.
#   tools/analysis_side_by_side.sh [OTHER_TREE]     default OTHER_TREE: /work/wt-old
# Settings (environment): BOARD (classic), SHOTS (4000), SEED (1), THREADS (1), ROUNDS (3).
# CPU s counts the whole process (engine start and the report too), wall s the analysis.
# The other tree needs its own build/tools.env (its tools/setup.sh). Prints one line per run
# and a table; the reports are kept in build/side_by_side/ (this build's last one is checked
# against the first: the figures must not move from run to run).
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
OTHER=$(cd "${1:-/work/wt-old}" && pwd)
BOARD=${BOARD:-classic}
SHOTS=${SHOTS:-4000}
SEED=${SEED:-1}
THREADS=${THREADS:-1}
ROUNDS=${ROUNDS:-3}
OUT="$ROOT/build/side_by_side"
mkdir -p "$OUT"
rm -f "$OUT"/this.* "$OUT"/other.*
[ -f "$OTHER/build/tools.env" ] || {
	echo "analysis_side_by_side: $OTHER has no build/tools.env (run its tools/setup.sh)" >&2
	exit 1
}

# One run of tree $1 (label $2, round $3): its report's JSON line into $OUT/$2.$3.json and
# the process's CPU seconds (user + system) into $OUT/$2.$3.cpu: on a busy machine the CPU
# time moves far less than the wall time.
run_one() {
	local tree=$1 label=$2 round=$3
	(cd "$tree" && /usr/bin/time -f '%U %S' -o "$OUT/$label.$round.time" tools/godot.sh \
		--headless --path . -- --analyze=pachinko --board="$BOARD" --shots="$SHOTS" \
		--seed="$SEED" --threads="$THREADS" 2>/dev/null) |
		grep -m1 '^{' >"$OUT/$label.$round.json"
	awk '{printf "%.2f\n", $1 + $2}' "$OUT/$label.$round.time" >"$OUT/$label.$round.cpu"
}

# A report's field (a number or string at the top level).
field() {
	python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])' "$1" "$2"
}

for round in $(seq 1 "$ROUNDS"); do
	for label in this other; do
		tree=$ROOT
		[ "$label" = other ] && tree=$OTHER
		run_one "$tree" "$label" "$round"
		f="$OUT/$label.$round.json"
		printf '  round %d %-5s %7.1f shots/s  %6.2f s  %6.2f CPU s\n' "$round" "$label" \
			"$(field "$f" shots_per_s)" "$(field "$f" wall_s)" "$(cat "$OUT/$label.$round.cpu")"
	done
done

# The figures that say which game was measured: the same in every run of one build.
same_game() {
	python3 - "$@" <<'EOF'
import json, sys
keep = lambda d: {k: v for k, v in d.items() if k not in ("wall_s", "shots_per_s", "profile")}
first = keep(json.load(open(sys.argv[1])))
for path in sys.argv[2:]:
    if keep(json.load(open(path))) != first:
        sys.exit("analysis_side_by_side: %s differs from %s beyond its timing" % (path, sys.argv[1]))
EOF
}
same_game "$OUT"/this.*.json
same_game "$OUT"/other.*.json

echo
echo "pachinko $BOARD, $SHOTS shots, seed $SEED, $THREADS thread(s), best of $ROUNDS (alternating;"
echo "shots/s and wall s from the run with the least wall time, CPU s the least of the runs)"
printf '| %-22s | %-10s | %-8s | %-8s | %-10s | %-7s | %-7s |\n' build "shots/s" "wall s" "CPU s" \
	ball_steps return version
printf '|%s|%s|%s|%s|%s|%s|%s|\n' ------------------------ ------------ ---------- ---------- \
	------------ --------- ---------
for label in this other; do
	tree=$ROOT
	[ "$label" = other ] && tree=$OTHER
	best=$(for f in "$OUT/$label".*.json; do echo "$(field "$f" wall_s) $f"; done | sort -n | head -1 | cut -d' ' -f2)
	cpu=$(sort -n "$OUT/$label".*.cpu | head -1)
	name="$label $(git -C "$tree" rev-parse --short HEAD)"
	printf '| %-22s | %10s | %8s | %8s | %10s | %7s | %7s |\n' "$name" \
		"$(field "$best" shots_per_s)" "$(field "$best" wall_s)" "$cpu" \
		"$(field "$best" ball_steps)" "$(field "$best" return)" "$(field "$best" version)"
done
