class_name AnalysisStats
extends RefCounted
## The statistics of a play analysis: 95% confidence intervals for rates (Wilson score)
## and for a mean (from the sample variance), dead pockets, and how far apart two pocket
## distributions are (total variation distance).

## z for a two-sided 95% interval.
const Z95 := 1.959963984540054
## A pocket is dead when, in every power band with shots, the upper 95% bound of its rate
## is below this.
const DEAD_RATE := 0.005


## The Wilson score interval [low, high] of a rate of `hits` in `n` trials at 95%;
## [0, 1] when n is 0 (nothing known).
static func wilson(hits: int, n: int) -> Vector2:
	if n <= 0:
		return Vector2(0.0, 1.0)
	var p := float(hits) / n
	var z2 := Z95 * Z95
	var denom := 1.0 + z2 / n
	var centre := (p + z2 / (2.0 * n)) / denom
	var half := Z95 * sqrt(p * (1.0 - p) / n + z2 / (4.0 * n * n)) / denom
	return Vector2(maxf(centre - half, 0.0), minf(centre + half, 1.0))


## Half the width of the Wilson 95% interval of `hits` in `n`.
static func rate_half_width(hits: int, n: int) -> float:
	var ci := wilson(hits, n)
	return (ci.y - ci.x) * 0.5


## The 95% half-width of the mean of `n` values whose sum is `total` and sum of squares
## `total_sq`, from the sample variance (normal approximation); INF below two values.
static func mean_half_width(total: int, total_sq: int, n: int) -> float:
	if n < 2:
		return INF
	var mean := float(total) / n
	var variance := maxf((float(total_sq) - mean * float(total)) / (n - 1), 0.0)
	return Z95 * sqrt(variance / n)


## Pockets whose rate's upper 95% bound is under DEAD_RATE in every band with shots (none
## when no band has shots).
static func dead_pockets(tally: AnalysisTally) -> PackedInt32Array:
	var dead := PackedInt32Array()
	for pocket in tally.pocket_count:
		var seen := false
		var alive := false
		for band in tally.band_count:
			var n := tally.band_shots[band]
			if n == 0:
				continue
			seen = true
			if wilson(tally.hits_in_band(band, pocket), n).y >= DEAD_RATE:
				alive = true
				break
		if seen and not alive:
			dead.append(pocket)
	return dead


## The distribution of catches over the pockets in `band` (sums to 1), or empty when the
## band caught nothing.
static func catch_distribution(tally: AnalysisTally, band: int) -> PackedFloat64Array:
	var out := PackedFloat64Array()
	var caught := 0
	for pocket in tally.pocket_count:
		caught += tally.hits_in_band(band, pocket)
	if caught == 0:
		return out
	for pocket in tally.pocket_count:
		out.append(float(tally.hits_in_band(band, pocket)) / caught)
	return out


## Total variation distance (half the sum of absolute differences) between two
## distributions of the same length: 0 the same, 1 nothing in common. -1 when either is
## empty or the lengths differ.
static func total_variation(p: PackedFloat64Array, q: PackedFloat64Array) -> float:
	if p.is_empty() or p.size() != q.size():
		return -1.0
	var sum := 0.0
	for i in p.size():
		sum += absf(p[i] - q[i])
	return sum * 0.5


## How differently the weakest and the strongest power band aim: the total variation
## distance between the pockets their catches land in; -1 when either caught nothing.
static func aim_distance(tally: AnalysisTally) -> float:
	return total_variation(
		catch_distribution(tally, 0), catch_distribution(tally, tally.band_count - 1)
	)
