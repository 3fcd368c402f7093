extends RefCounted
## Hard mode's look-before-you-tilt: before the pilot commits to a tilt, a private copy of
## the board (same walls, same holes) plays the next moment with the balls where they are
## now. If a ball would fall, the guard tries gentler tilts and picks the one that keeps
## every ball out of the holes longest.

## How far ahead a tilt is tried, seconds, and how often the choice is renewed.
const HORIZON := 0.6
const RECHECK := 0.2
## Gentler tilts tried, as shares of the wanted tilt (0 = flat board).
const SHARES: Array[float] = [1.0, 0.6, 0.3, 0.0]
## Brakes tried when even a flat board is not safe: against the balls' mean motion.
const BRAKE_DEG := 6.0
## Between checks a wish passes unchecked only while it stays this close to the tilt last
## checked, degrees per axis: a steering loop's small corrections pass, but a new plan's
## first tilt (often the other way) is checked at once.
const TRUST_SLACK_DEG := 2.0

var _probe: BallWorld
var _radius := 5.0
var _dt := 1.0 / 120.0
var _fell := false
var _since_check := INF
var _choice := Vector2.ZERO
var _trusted := false
var _checked := Vector2.ZERO


func _init(level: BoardLevel, dt: float) -> void:
	_probe = BoardWorldFactory.build(level, true)
	_radius = level.ball_radius
	_dt = dt
	if _probe != null:
		_probe.ball_fell_in_hole.connect(_on_fell)


## The tilt to use instead of `wanted` for balls at `positions` moving at `velocities`.
func filter(
	wanted: Vector2, positions: PackedVector2Array, velocities: PackedVector2Array
) -> Vector2:
	if _probe == null:
		return wanted
	_since_check += _dt
	var changed := wanted.distance_to(_checked) > TRUST_SLACK_DEG
	if _since_check < RECHECK and not changed:
		# Between checks a safe wish passes live (a steering loop needs its feedback); an
		# overruled one stays overruled until the next check.
		return wanted if _trusted else _choice
	_since_check = 0.0
	_checked = wanted
	var candidates: Array[Vector2] = []
	for share in SHARES:
		candidates.append(wanted * share)
	var mean_v := Vector2.ZERO
	for v in velocities:
		mean_v += v
	if mean_v.length() > 1.0:
		candidates.append(-mean_v.normalized() * BRAKE_DEG)
	var best := wanted
	var best_time := _survives(wanted, positions, velocities)
	_trusted = best_time >= HORIZON
	if _trusted:
		return wanted
	for tilt: Vector2 in candidates.slice(1):
		var survived := _survives(tilt, positions, velocities)
		if survived >= HORIZON:
			best = tilt
			break
		if survived > best_time:
			best_time = survived
			best = tilt
	_choice = best
	return _choice


# Seconds the balls last under `tilt` before one falls (HORIZON when none does).
func _survives(
	tilt: Vector2, positions: PackedVector2Array, velocities: PackedVector2Array
) -> float:
	_probe.clear_balls()
	for i in positions.size():
		_probe.spawn_ball(positions[i], velocities[i], _radius)
	MazeTilt.apply(_probe, tilt)
	_fell = false
	var t := 0.0
	while t < HORIZON:
		_probe.step(_dt)
		t += _dt
		if _fell:
			return t
	return HORIZON


func _on_fell(_ball_id: int, _hole_index: int) -> void:
	_fell = true
