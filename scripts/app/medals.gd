class_name Medals
extends RefCounted
## Bronze, silver and gold for maze times. A board's medal times per mode are stored in its
## file (`medal_times` → BoardLevel.medal_times_easy / _hard, [gold, silver, bronze] in
## seconds); the medal a player holds is computed from their best time for that board and
## mode (SaveData), so nothing extra is saved.

enum Medal { NONE, BRONZE, SILVER, GOLD }

## Medal times as multiples of the autoplay pilot's time (tools/maze_pilot_table.gd). The
## pilot plans every tilt with the whole maze in view and reacts every step, so gold asks a
## player for half as long again as it needs. Silver is 1.8 x gold and bronze 3.5 x gold, a
## first clean finish: with 1.47 x and 2.33 x (trial 7) most first finishes from board 3 on
## (30 to 50 s) got no medal, and Cloister's bronze was missed by 1.6 s (49.1 s against 47.5).
const GOLD_FACTOR := 1.5
const SILVER_FACTOR := GOLD_FACTOR * 1.8
const BRONZE_FACTOR := GOLD_FACTOR * 3.5
const NAMES := ["No medal", "Bronze", "Silver", "Gold"]


## [gold, silver, bronze] for a board the pilot finished in `pilot_seconds`, rounded up to
## a tenth of a second.
static func from_pilot_time(pilot_seconds: float) -> PackedFloat64Array:
	var times := PackedFloat64Array()
	for factor: float in [GOLD_FACTOR, SILVER_FACTOR, BRONZE_FACTOR]:
		times.append(ceilf(pilot_seconds * factor * 10.0) / 10.0)
	return times


## The medal times of `level` in hard or easy mode (empty when it has none).
static func times_for(level: BoardLevel, hard: bool) -> PackedFloat64Array:
	if level == null:
		return PackedFloat64Array()
	return level.medal_times_hard if hard else level.medal_times_easy


## The medal a finish in `seconds` earns against `times` ([gold, silver, bronze]); a time
## of 0 or less (not finished) earns none.
static func medal_for_time(times: PackedFloat64Array, seconds: float) -> Medal:
	if times.size() != 3 or not is_finite(seconds) or seconds <= 0.0:
		return Medal.NONE
	# judged on the time as the clock shows it (whole tenths, rounded down): a run the clock
	# calls 0:22.8 earns a 22.8 s gold, as the player reads it
	seconds = shown_time(seconds)
	if seconds <= times[0]:
		return Medal.GOLD
	if seconds <= times[1]:
		return Medal.SILVER
	if seconds <= times[2]:
		return Medal.BRONZE
	return Medal.NONE


## `seconds` as the game's clock shows it: whole tenths, rounded down (the nudge keeps 36.3
## from reading 36.2, as 36.3 * 10 is 362.99999... in binary).
static func shown_time(seconds: float) -> float:
	return floorf(maxf(seconds, 0.0) * 10.0 + 1e-6) / 10.0


## The medal of a best time `best_seconds` (-1 = never finished) on `level` in that mode.
static func medal(level: BoardLevel, hard: bool, best_seconds: float) -> Medal:
	return medal_for_time(times_for(level, hard), best_seconds)


## "Gold", "Silver", "Bronze" or "No medal".
static func name_of(which: Medal) -> String:
	return NAMES[which]


## The best medal a run at `elapsed` seconds can still earn against `times` ([gold, silver,
## bronze]) and its time: {"medal": Medal, "seconds": float}; Medal.NONE and 0 once every
## time has passed (or the board has none).
static func next_target(times: PackedFloat64Array, elapsed: float) -> Dictionary:
	if times.size() == 3:
		for rank in 3:
			if shown_time(elapsed) <= times[rank]:
				return {
					"medal": [Medal.GOLD, Medal.SILVER, Medal.BRONZE][rank], "seconds": times[rank]
				}
	return {"medal": Medal.NONE, "seconds": 0.0}


## The time `which` asks for in `times` ([gold, silver, bronze]); -1 for NONE or no times.
static func time_of(times: PackedFloat64Array, which: Medal) -> float:
	if times.size() != 3 or which == Medal.NONE:
		return -1.0
	return times[Medal.GOLD - which]
