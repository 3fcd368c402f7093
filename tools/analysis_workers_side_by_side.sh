#!/usr/bin/env bash
# The pachinko analysis on threads against worker processes (--workers), side by side in one
# run: 1 thread, 2 threads, 1 worker, 2 workers (each beside this process, which fires
# its share of the queue too) take turns on each board, ROUNDS times, so
# a busy moment on a shared machine costs each alike; each mode's best run is its figure.
# Every report must equal the 1-thread one apart from its timing fields (wall_s,
# shots_per_s), its threads setting and where it was written; exits 1 when one differs.
#   tools/analysis_workers_side_by_side.sh
# Settings (environment): BOARDS ("classic fever"), SHOTS (10000), SEED (1), ROUNDS (2).
# shots/s here is SHOTS over the whole command's wall time (engine start, the bonus-open
# second run of a board with bonus pockets and the report included), so every mode pays
# the same; CPU s is the command's user + system time with its reaped worker processes.
# The reports are kept in build/workers_side_by_side/.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BOARDS=${BOARDS:-classic fever}
SHOTS=${SHOTS:-10000}
SEED=${SEED:-1}
ROUNDS=${ROUNDS:-2}
OUT="$ROOT/build/workers_side_by_side"
MODES=("t1:--workers=0 --threads=1" "t2:--workers=0 --threads=2" "w1:--workers=1"
	"w2:--workers=2")
mkdir -p "$OUT"
rm -f "$OUT"/*.json "$OUT"/*.time

for round in $(seq 1 "$ROUNDS"); do
	for board in $BOARDS; do
		for mode in "${MODES[@]}"; do
			label=${mode%%:*}
			read -r -a flags <<<"${mode#*:}"
			stem="$OUT/$board.$label.$round"
			(cd "$ROOT" && /usr/bin/time -f '%e %U %S' -o "$stem.time" tools/godot.sh \
				--headless --path . -- --analyze=pachinko --board="$board" --shots="$SHOTS" \
				--seed="$SEED" "${flags[@]}" --out="$OUT/reports.$label" 2>"$stem.err") |
				grep -m1 '^{' >"$stem.json"
			read -r wall user sys <"$stem.time"
			printf '  round %d %-8s %-3s %7.1f shots/s  %6.2f s  %6.2f CPU s\n' "$round" "$board" \
				"$label" "$(echo "$SHOTS / $wall" | bc -l)" "$wall" "$(echo "$user + $sys" | bc -l)"
		done
	done
done

python3 - "$OUT" "$SHOTS" "$ROUNDS" "$BOARDS" <<'PY'
import json, sys
out, shots, rounds, boards = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4].split()
modes = ["t1", "t2", "w1", "w2"]
names = {"t1": "1 thread", "t2": "2 threads", "w1": "1 worker + this", "w2": "2 workers + this"}
timing = ("wall_s", "shots_per_s", "threads", "report", "heatmap")
keep = lambda d: {k: v for k, v in d.items() if k not in timing}
ok = True
print("\n%-8s %-17s %12s %8s %8s %s" % ("board", "run", "shots/s", "wall s", "CPU s", "report"))
for board in boards:
    first = keep(json.load(open("%s/%s.t1.1.json" % (out, board))))
    for mode in modes:
        walls, cpus, same = [], [], True
        for r in range(1, rounds + 1):
            stem = "%s/%s.%s.%d" % (out, board, mode, r)
            wall, user, sys_ = map(float, open(stem + ".time").read().split())
            walls.append(wall)
            cpus.append(user + sys_)
            same = same and keep(json.load(open(stem + ".json"))) == first
        ok = ok and same
        best = min(walls)
        print("%-8s %-17s %12.1f %8.2f %8.2f %s" % (board, names[mode], shots / best, best,
              cpus[walls.index(best)], "same as 1 thread" if same else "DIFFERS"))
sys.exit(0 if ok else 1)
PY
