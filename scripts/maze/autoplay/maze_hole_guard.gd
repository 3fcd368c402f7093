class_name MazeHoleGuard
extends RefCounted
## Hard mode's look-before-you-tilt: before the pilot commits to a tilt, a private copy of
## the board (same walls, the holes grown by MARGIN) plays the next moment with the balls
## where they are now. If a ball would come that near a hole, the guard tries gentler tilts
## and picks the one that keeps every ball clear longest; when none keeps that room (a ball
## is already close), a second copy with the true holes picks the one that keeps every
## ball out longest.

## Room the guard keeps between a ball's centre and a hole's rim, px.
const MARGIN := 6.0
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

## The board with grown holes, and with the true ones.
var _probe: BallWorld
var _true_probe: BallWorld
var _world: BallWorld
var _radius := 5.0
var _dt := 1.0 / 120.0
var _fell := false
var _since_check := INF
var _choice := Vector2.ZERO
var _trusted := false
var _checked := Vector2.ZERO


func _init(level: BoardLevel, dt: float) -> void:
	var grown := level.duplicate() as BoardLevel
	grown.hole_radius = level.hole_radius + MARGIN
	_probe = BoardWorldFactory.build(grown, true)
	_true_probe = BoardWorldFactory.build(level, true)
	_radius = level.ball_radius
	_dt = dt
	if _probe == null or _true_probe == null:
		_probe = null
		return
	_probe.ball_fell_in_hole.connect(_on_fell)
	_true_probe.ball_fell_in_hole.connect(_on_fell)


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
	_world = _probe
	var best_time := _survives(wanted, positions, velocities)
	_trusted = best_time >= HORIZON
	if _trusted:
		return wanted
	_choice = _safest(candidates, positions, velocities)
	if _choice == Vector2.INF:
		_world = _true_probe
		_choice = _safest(candidates, positions, velocities)
	if _choice == Vector2.INF:
		_choice = candidates[0]
	# A wish that is safe enough after all passes live, as a trusted one does.
	_trusted = _choice == wanted
	return _choice


# The first of `candidates` that lasts the horizon in `_world`; else, in the true-hole
# world, the one that lasts longest; Vector2.INF when the grown-hole world has none.
func _safest(
	candidates: Array[Vector2], positions: PackedVector2Array, velocities: PackedVector2Array
) -> Vector2:
	var best := Vector2.INF
	var best_time := -1.0
	for tilt: Vector2 in candidates:
		var survived := _survives(tilt, positions, velocities)
		if survived >= HORIZON:
			return tilt
		if survived > best_time:
			best_time = survived
			best = tilt
	return best if _world == _true_probe else Vector2.INF


# Seconds the balls last under `tilt` before one falls (HORIZON when none does).
func _survives(
	tilt: Vector2, positions: PackedVector2Array, velocities: PackedVector2Array
) -> float:
	_world.clear_balls()
	for i in positions.size():
		_world.spawn_ball(positions[i], velocities[i], _radius)
	MazeTilt.apply(_world, tilt)
	_fell = false
	var t := 0.0
	while t < HORIZON:
		_world.step(_dt)
		t += _dt
		if _fell:
			return t
	return HORIZON


func _on_fell(_ball_id: int, _hole_index: int) -> void:
	_fell = true
