class_name PocketApproach
extends RefCounted
## Tells which ball is about to drop into a pocket: each ball's path is followed ahead on
## its parabola (its velocity and the board's gravity, no bounces) for LOOKAHEAD game
## seconds, and a ball whose path crosses a pocket's mouth going down, or that is already
## inside a cup above its catching pin, is "about to enter". Only reads the world; the
## slow motion asks it once a frame, and only for the last balls of a game.

## Game seconds of path followed ahead of each ball.
const LOOKAHEAD := 0.3
## Points checked along that path.
const SAMPLES := 8
## Share of a mouth's half width a path must cross within (its edges bounce balls out).
const MOUTH_SHARE := 0.85

## Per pocket the ball can enter: the mouth centre, its half width and the catching pin's
## depth below it. Regular pockets first, then the bonus pockets (world pocket id order).
var _mouths := PackedVector2Array()
var _half_widths := PackedFloat32Array()
var _depths := PackedFloat32Array()
## Per mouth: the attacker's bonus pocket index, or -1 (any other pocket always takes
## balls; a shut attacker's lid covers its mouth).
var _attacker := PackedInt32Array()
var _gravity := Vector2.ZERO


## Reads the pockets of `level` and the gravity of `world` (px/s²).
func _init(level: BoardLevel, gravity: Vector2) -> void:
	_gravity = gravity
	for spec in level.pockets:
		_add_mouth(spec, -1)
	for i in level.bonus_pockets.size():
		var spec := level.bonus_pockets[i]
		var attacker := spec != null and spec.role == BonusPocketSpec.Role.ATTACKER
		_add_mouth(spec, i if attacker else -1)


## Pockets this approach watches.
func mouth_count() -> int:
	return _mouths.size()


## The id of a ball in `world` about to drop into an enterable pocket (`machine` says
## which attackers are open; null: every one is), or -1; ball `skip` never counts. The
## first such ball in the world's order wins, so the answer is the same every run.
func find_ball(world: BallWorld, machine: BonusMachine, skip: int = -1) -> int:
	var ids := world.get_ids()
	var positions := world.get_positions()
	var velocities := world.get_velocities()
	for i in ids.size():
		if ids[i] != skip and entering(positions[i], velocities[i], machine):
			return ids[i]
	return -1


## True while ball `id` of `world` is still about to enter a pocket.
func ball_entering(world: BallWorld, id: int, machine: BonusMachine) -> bool:
	if not world.has_ball(id):
		return false
	return entering(world.get_ball_position(id), world.get_ball_velocity(id), machine)


## True when a ball at `at` moving at `velocity` is inside a cup or will cross a mouth
## going down within LOOKAHEAD seconds.
func entering(at: Vector2, velocity: Vector2, machine: BonusMachine) -> bool:
	for m in _mouths.size():
		if not _enterable(m, machine):
			continue
		if _inside_cup(m, at) or _path_crosses_mouth(m, at, velocity):
			return true
	return false


func _add_mouth(spec: PocketSpec, attacker_index: int) -> void:
	if spec == null or spec.width <= 0.0:
		return
	_mouths.append(spec.position)
	_half_widths.append(spec.width * 0.5)
	_depths.append(maxf(spec.depth, 0.0))
	_attacker.append(attacker_index)


func _enterable(m: int, machine: BonusMachine) -> bool:
	var index := _attacker[m]
	return index < 0 or machine == null or machine.is_open(index)


func _inside_cup(m: int, at: Vector2) -> bool:
	var mouth := _mouths[m]
	var below := at.y - mouth.y
	return below >= 0.0 and below <= _depths[m] and absf(at.x - mouth.x) < _half_widths[m]


func _path_crosses_mouth(m: int, at: Vector2, velocity: Vector2) -> bool:
	var mouth := _mouths[m]
	if at.y >= mouth.y:
		return false
	var reach := _half_widths[m] * MOUTH_SHARE
	var before := at
	for s in range(1, SAMPLES + 1):
		var t := LOOKAHEAD * float(s) / float(SAMPLES)
		var after := at + velocity * t + _gravity * (0.5 * t * t)
		if after.y >= mouth.y and after.y > before.y:
			# Where the step between the two points crosses the mouth's line.
			var k := (mouth.y - before.y) / (after.y - before.y)
			var x := lerpf(before.x, after.x, k)
			return absf(x - mouth.x) < reach
		before = after
	return false
