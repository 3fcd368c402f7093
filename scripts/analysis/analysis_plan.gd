class_name AnalysisPlan
extends RefCounted
## What a pachinko play analysis should do: the board, how many shots, the power each shot
## gets, the RNG seed, and how the work is cut up. The figures depend only on the board,
## `shots`, `rng_seed`, the power range and `played`: shots are split into fixed chunks of
## CHUNK_SHOTS, each with its own seed, whatever the thread count.

## Shots per chunk: one chunk runs in one world on one thread, start to end.
const CHUNK_SHOTS := 250
## Power bands the report splits the power range into (the aim map's rows).
const BAND_COUNT := 5
## Longest a ball is followed, seconds of game time, before it counts as stuck.
const MAX_BALL_SECONDS := 20.0
## Powers are drawn on the rules' own grid (hundredths of a point: what a player can fire).
## Every shot of one power climbs the rail the same way (the climb is simulated once per
## power) and, with no ball in its way and nothing moving, meets the pins the same way too:
## shots that share a power are one sample, not many. So the grid must be as fine as the
## game's, or the analysis measures a few hundred paths and calls them thousands.
const POWER_STEP := PachinkoRules.POWER_STEP
## Shots the editor's Analyze button fires (and the cache's default entry).
const EDITOR_SHOTS := 10000
## Side of a density grid cell in board pixels.
const DENSITY_CELL := 5.0

## The board analysed (a pachinko board).
var level: BoardLevel
## Number of shots to fire.
var shots := 10000
## RNG seed: the same seed and shots give the same figures.
var rng_seed := 1
## Worker threads (1 runs every chunk on the calling thread).
var threads := 1
## Each shot's power is uniform over power_from..power_to (0..100 is the whole range).
var power_from := 0.0
var power_to := 100.0
## True: shots are fired as a player fires them, one at a time at the autoplay's pace
## among the balls in play, with ball contacts on (PlayedShotChunk): the return a player
## gets, at about seven times the CPU. False (the default, and the editor's Analyze): many
## balls at once that pass through each other (PachinkoShotChunk), each as if alone. On
## Classic the two differ by less than the report's interval (0.850 and 0.844 against
## ±0.04; balls knocking each other off their paths cost about 0.017), while the played
## run takes minutes where a designer waits for it.
var played := false
## Balls in flight at once in one world when not `played`. They pass through each other
## (no ball-ball contacts), so each flies as if alone; more at once only shares the
## per-step cost.
var in_flight := 125
## True: every bonus pocket stays open the whole run (attacker lids up, tulip wings
## spread), to measure what they catch in the rounds the rules open them for (BonusEstimate).
var bonus_open := false

var _level_order := PackedInt32Array()
## The first level and the count _level_order was made for.
var _order_range := Vector2i(-1, 0)
var _order_mutex := Mutex.new()


## A plan for `shot_count` shots on `board` with the RNG seed `seed_value`.
static func create(board: BoardLevel, shot_count: int, seed_value: int) -> AnalysisPlan:
	var plan := AnalysisPlan.new()
	plan.level = board
	plan.shots = shot_count
	plan.rng_seed = seed_value
	return plan


## A copy of this plan with every bonus pocket held open (same shots, seed and powers).
func with_bonus_open() -> AnalysisPlan:
	var copy := AnalysisPlan.create(level, shots, rng_seed)
	copy.threads = threads
	copy.power_from = power_from
	copy.power_to = power_to
	copy.in_flight = in_flight
	copy.played = played
	copy.bonus_open = true
	return copy


## What is wrong with the plan, or "" when it can run.
func problem() -> String:
	if level == null or not level.is_pachinko() or level.ring_radius <= 0.0:
		return "the analysis needs a pachinko board with a ring"
	if shots < 1:
		return "the analysis needs at least one shot (got %d)" % shots
	if not (is_finite(power_from) and is_finite(power_to)):
		return "the power range must be finite numbers"
	if power_from < 0.0 or power_to > 100.0 or power_from > power_to:
		return "the power range must lie within 0..100 (got %s..%s)" % [power_from, power_to]
	if in_flight < 1:
		return "at least one ball must be in flight (got %d)" % in_flight
	return ""


## Number of chunks the shots are cut into.
func chunk_count() -> int:
	return ceili(float(shots) / CHUNK_SHOTS)


## Shots in chunk `index` (the last chunk may be short).
func chunk_shots(index: int) -> int:
	return mini(CHUNK_SHOTS, shots - index * CHUNK_SHOTS)


## The RNG seed of chunk `index` (a played run's pauses and nudges): it depends only on the
## plan's seed and the index.
func chunk_seed(index: int) -> int:
	return hash([rng_seed, index, "pachinko-analysis"])


## Power levels on the POWER_STEP grid over 0..100.
static func level_count() -> int:
	return roundi(100.0 / POWER_STEP) + 1


## The power level (index on the POWER_STEP grid) nearest `power`.
static func level_of(power: float) -> int:
	return clampi(roundi(power / POWER_STEP), 0, level_count() - 1)


## The power of level `power_level`.
static func power_of(power_level: int) -> float:
	return power_level * POWER_STEP


## The power level of each shot of chunk `index`, in firing order. The run draws its levels
## without putting them back: the range's levels (POWER_STEP apart) in an order shuffled by
## the plan's seed, shot after shot (starting over once every level was fired). Each shot
## is still equally likely to get any level of the range, but no level is fired twice
## before every level was fired once: 10000 shots on 0..100 fire all but one of the 10001
## levels, so the figures no longer depend on which powers chance picked (with independent
## draws they did by about ±0.02 of return on Classic).
func chunk_levels(index: int) -> PackedInt32Array:
	var order := level_order()
	var out := PackedInt32Array()
	out.resize(chunk_shots(index))
	for k in out.size():
		out[k] = order[(index * CHUNK_SHOTS + k) % order.size()]
	return out


## Every power level of the range, in the plan's shuffled firing order. Made once per plan
## (chunks on any thread share it).
func level_order() -> PackedInt32Array:
	var first := level_of(power_from)
	var count := level_of(power_to) - first + 1
	_order_mutex.lock()
	if _order_range != Vector2i(first, count):
		_order_range = Vector2i(first, count)
		var rng := RandomNumberGenerator.new()
		rng.seed = hash([rng_seed, first, count, "pachinko-analysis-levels"])
		var order := PackedInt32Array()
		order.resize(count)
		for i in count:
			order[i] = first + i
		for i in range(count - 1, 0, -1):
			var j := rng.randi_range(0, i)
			var kept := order[i]
			order[i] = order[j]
			order[j] = kept
		_level_order = order
	var out := _level_order
	_order_mutex.unlock()
	return out


## The power band (0..BAND_COUNT-1) a shot of `power` belongs to: the whole 0..100 range
## cut in five equal bands, so bands mean the same power on every plan.
static func band_of(power: float) -> int:
	return clampi(int(power / (100.0 / BAND_COUNT)), 0, BAND_COUNT - 1)


## The power range of band `band`: [from, to].
static func band_range(band: int) -> Vector2:
	var width := 100.0 / BAND_COUNT
	return Vector2(band * width, (band + 1) * width)
