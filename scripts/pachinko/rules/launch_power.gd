extends RefCounted
## Flipper power (0..100) to launch speed at the bottom of the physical launch rail.
##
## The chapter fires balls into the field at 3.5 to 10 px per 30 ms tick (117 to 333 px/s).
## Here the ball climbs a real rail first, so the speed it needs at the bottom follows from
## energy: v_bottom² = v_exit² + v_clear², with v_clear ≈ sqrt(2·g·Δh) the slowest launch
## that passes the rail's top (measured on the board). Below `CLEAR_POWER` the ball cannot
## clear and rolls back to the cup; from there up the exit speed rises linearly through
## the chapter's range.

## Field entry speed at the weakest clearing shot (chapter 3.5 px/tick at 30 ms).
const EXIT_SPEED_MIN := 3.5 / 0.03
## Field entry speed at full power (chapter 10 px/tick, its maximum speed).
const EXIT_SPEED_MAX := 10.0 / 0.03
## Powers below this roll back down the rail.
const CLEAR_POWER := 12.0
## The strongest rolling-back shot still climbs this share of the way (by speed).
const WEAK_SHOT_SHARE := 0.93
## The weakest shot (power 0) climbs only this share.
const ZERO_SHOT_SHARE := 0.45
const MAX_POWER := 100.0


## Intended speed at the rail exit for `power`, or 0 for a shot that rolls back.
static func exit_speed(power: float) -> float:
	if power < CLEAR_POWER:
		return 0.0
	var t := (clampf(power, 0.0, MAX_POWER) - CLEAR_POWER) / (MAX_POWER - CLEAR_POWER)
	return lerpf(EXIT_SPEED_MIN, EXIT_SPEED_MAX, t)


## Speed at the bottom of the rail for `power`, given `clear`: the slowest launch that
## still leaves the rail (measured by LaunchCalibration). A clearing shot adds its exit
## speed's energy on top (v² = clear² + v_exit²), so it leaves the rail at about v_exit; a
## weak shot carries less than `clear` and rolls back.
static func launch_speed(power: float, clear: float) -> float:
	var v_exit := exit_speed(power)
	if v_exit > 0.0:
		return sqrt(clear * clear + v_exit * v_exit)
	var share := lerpf(
		ZERO_SHOT_SHARE, WEAK_SHOT_SHARE, clampf(power, 0.0, MAX_POWER) / CLEAR_POWER
	)
	return clear * share


## Power (0..100) from a drag: the chapter measures how far the pointer moved up from where
## the press began, one pixel per point of power.
static func power_from_drag(origin: Vector2, point: Vector2) -> float:
	return clampf(origin.y - point.y, 0.0, MAX_POWER)


## Flipper rotation for a power: 0 to 20 degrees (the chapter's power / 5).
static func flipper_degrees(power: float) -> float:
	return clampf(power, 0.0, MAX_POWER) / 5.0
