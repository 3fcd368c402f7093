class_name LaunchPreview
extends RefCounted
## Where a shot of each power goes once it leaves the launch rail, as the game's own physics
## flies it: one lone ball per power (every STEP points, 0..100) is launched the way the
## rules launch it (LaunchRail's start and direction, the board's LaunchTable), in a world
## of the board with ball contacts off, and followed from the rail's mouth
## (LaunchRail.entry_point) until it meets its first pin. The view draws that flight while
## the player aims, so what power does is shown, not guessed: with no other ball in the way
## a shot of that power flies exactly so (the handle's spring spreads its balls over
## LaunchHandle.JITTER either side).

## Powers apart of two measured flights.
const STEP := 1.0
## Longest a flight is followed, seconds.
const MAX_SECONDS := 2.5
## A flight keeps a point every this many steps.
const SAMPLE_EVERY := 3

## Per measured power (index = power / STEP): the flight's points from the rail's mouth to
## its first pin, and where it met that pin.
var paths: Array[PackedVector2Array] = []
var landings := PackedVector2Array()
## Where every shot leaves the rail.
var exit_point := Vector2.ZERO


## Flies one ball per STEP of power on `level` (a pachinko board), launched through its
## LaunchCalibration table as the rules launch them.
static func measure(level: BoardLevel) -> LaunchPreview:
	var launch := LaunchCalibration.table(level)
	var preview := LaunchPreview.new()
	preview.exit_point = LaunchRail.entry_point(level)
	var count := int(100.0 / STEP) + 1
	preview.paths.resize(count)
	preview.landings.resize(count)
	var world := BoardWorldFactory.build(level)
	world.threads = 1
	world.ball_contacts = false
	var start := LaunchRail.launch_position(level)
	var direction := LaunchRail.launch_direction(level)
	var centre := level.ring_center
	var sweep := deg_to_rad(absf(level.rail_end_deg - level.rail_start_deg))
	var sense := -1.0 if level.rail_end_deg < level.rail_start_deg else 1.0
	var start_angle := (start - centre).angle()
	var travelled := PackedFloat32Array()
	var last_angle := PackedFloat32Array()
	var landed := PackedByteArray()
	for k in count:
		var speed := launch.launch_speed(k * STEP)
		var id := world.spawn_ball(start, direction * speed, level.ball_radius)
		assert(id == k)
		preview.paths[k] = PackedVector2Array([preview.exit_point])
		preview.landings[k] = preview.exit_point
		travelled.append(0.0)
		last_angle.append(start_angle)
		landed.append(0)
	var hits: Array[int] = []
	world.pin_hit.connect(func(ball: int, _pin: int, _speed: float) -> void: hits.append(ball))
	var dt := 1.0 / maxf(world.tuning.fixed_hz, 1.0)
	for step in int(MAX_SECONDS / dt):
		if world.ball_count() == 0:
			break
		hits.clear()
		world.step(dt)
		var ids := world.get_ids()
		var pos := world.get_positions()
		var done := PackedInt32Array()
		for i in ids.size():
			var k := ids[i]
			var angle := (pos[i] - centre).angle()
			travelled[k] += wrapf(angle - last_angle[k], -PI, PI) * sense
			last_angle[k] = angle
			var past_mouth := travelled[k] > sweep
			if past_mouth and (step % SAMPLE_EVERY == 0 or hits.has(k)):
				preview.paths[k].append(pos[i])
			if hits.has(k):
				preview.landings[k] = pos[i]
				landed[k] = 1
				done.append(k)
		if not done.is_empty():
			world.remove_balls(done)
	for k in count:
		if landed[k] == 0 and preview.paths[k].size() > 1:
			preview.landings[k] = preview.paths[k][preview.paths[k].size() - 1]
	return preview


## The flight of a shot of `power` (0..100) from the rail's mouth to its first pin.
func path(power: float) -> PackedVector2Array:
	return paths[_index(power)] if not paths.is_empty() else PackedVector2Array()


## Where a shot of `power` (0..100) first meets a pin (the ball's centre then).
func landing(power: float) -> Vector2:
	return landings[_index(power)] if not landings.is_empty() else exit_point


func _index(power: float) -> int:
	return clampi(roundi(clampf(power, 0.0, 100.0) / STEP), 0, paths.size() - 1)
