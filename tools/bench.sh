#!/usr/bin/env bash
# make bench: runs every tests/bench/bench_*.gd headless (each writes build/bench/<name>.json)
# and fails if any of them fails. Nothing is pinned: BallWorld steps its per-ball stages on
# every core, and GodotPhysics2D gets the same cores for its worker pool. bench_analysis.gd
# times the pachinko play analysis (shots/s on Classic and Fever, 1 thread and every core).
# Arguments go to the benchmarks: `tools/bench.sh --only=S4` is a quick look at one scenario
# (bench_physics.gd reads it; the others ignore it).
set -uo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
mkdir -p build/bench
failed=0
shopt -s nullglob
benches=(tests/bench/bench_*.gd)
if [ ${#benches[@]} -eq 0 ]; then
	echo "bench: no tests/bench/bench_*.gd found" >&2
	exit 1
fi
for b in "${benches[@]}"; do
	echo "== $b"
	log=build/bench/$(basename "$b" .gd).log
	tools/godot.sh --headless --path . -s "res://$b" -- "$@" 2>&1 | tee "$log"
	status=${PIPESTATUS[0]}
	if [ "$status" -ne 0 ] || grep -qE '^(SCRIPT ERROR|Parse Error)' "$log"; then
		echo "bench: $b failed (exit $status)" >&2
		failed=$((failed + 1))
	fi
done
if [ "$failed" -ne 0 ]; then
	echo "bench: $failed benchmark(s) failed" >&2
	exit 1
fi
echo "bench: all ${#benches[@]} benchmark(s) passed"
