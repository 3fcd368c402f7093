class_name RailClimber
extends RefCounted
## Simulates the rail climb of a group of shot powers for RailExitTable: one world of the
## board (the very world the shots fly in, so the hand-over is exact), one ball per power
## with ball contacts off, followed until it rolls back into the return zone, or is past
## the rail's end in free flight and, when the table asks for it (RailExitTable.to_first_pin),
## has met its first pin (where power aimed it).

var _level: BoardLevel
var _launch: LaunchTable
var _world: BallWorld
var _table: RailExitTable
## Per ball id: its power level, the ring angle it was last at and how far it went round.
var _level_of := PackedInt32Array()
var _last_angle := PackedFloat32Array()
var _travelled := PackedFloat32Array()
var _last_vel := PackedVector2Array()
## Per ball id: 1 once its hand-over state is taken, and 1 once it met a pin.
var _handed := PackedByteArray()
var _met_pin := PackedByteArray()
var _step := 0
var _ball_steps := 0
## Per ball id: the density cells it passed (moved into the table at the end). Kept here,
## with the board's numbers below, so the per-ball loop reads only this object's members
## (see PachinkoShotChunk._density).
var _cells: Array[PackedInt32Array] = []
var _centre := Vector2.ZERO
var _board_size := Vector2.ZERO
## False: a ball is removed at its hand-over, met a pin or not.
var _to_first_pin := true


## Climbs every power level in `levels` side by side on `level` (a pachinko board) and
## returns a table holding their results (other levels stay UNKNOWN). Thread-safe: it
## touches nothing shared but `profile` (when given, the climb's steps are counted into it).
## `launch` is LaunchCalibration.table(level). `to_first_pin` false stops each climb at its
## hand-over (see RailExitTable.to_first_pin).
static func climb_group(
	level: BoardLevel,
	launch: LaunchTable,
	levels: PackedInt32Array,
	profile: AnalysisProfile = null,
	to_first_pin := true
) -> RailExitTable:
	var climber := RailClimber.new(level, launch)
	climber._to_first_pin = to_first_pin
	var table := climber.climb(levels)
	if profile != null:
		profile.climb_groups += 1
		profile.climb_steps += climber._step
		profile.climb_ball_steps += climber._ball_steps
	return table


func _init(level: BoardLevel, launch: LaunchTable) -> void:
	_level = level
	_launch = launch


## Climbs `levels`; returns a table with their fates.
func climb(levels: PackedInt32Array) -> RailExitTable:
	_table = RailExitTable.new()
	_table.to_first_pin = _to_first_pin
	_centre = _level.ring_center
	_board_size = _level.size
	_world = BoardWorldFactory.build(_level)
	_world.threads = 1
	_world.ball_contacts = false
	_world.ball_entered_zone.connect(_on_zone)
	_world.ball_drained.connect(_on_gone)
	_world.ball_captured.connect(_on_pocketed)
	_world.pin_hit.connect(_on_pin_hit)
	var start := LaunchRail.launch_position(_level)
	var direction := LaunchRail.launch_direction(_level)
	var start_angle := (start - _level.ring_center).angle()
	for q in levels:
		var speed := _launch.launch_speed(AnalysisPlan.power_of(q))
		var id := _world.spawn_ball(start, direction * speed, _level.ball_radius)
		_level_of.append(q)
		_last_angle.append(start_angle)
		_travelled.append(0.0)
		_last_vel.append(direction * speed)
		_cells.append(PackedInt32Array())
		_handed.append(0)
		_met_pin.append(0)
		assert(id == _level_of.size() - 1)
	var dt := 1.0 / maxf(_world.tuning.fixed_hz, 1.0)
	var max_steps := int(RailExitTable.MAX_SECONDS / dt)
	while _world.ball_count() > 0 and _step < max_steps:
		_ball_steps += _world.ball_count()
		_world.step(dt)
		_step += 1
		_follow(dt)
	for id in _world.get_ids():
		if _handed[id] == 0:
			_table.fate[_level_of[id]] = RailExitTable.Fate.FULL
	for id in _level_of.size():
		_table.samples[_level_of[id]] = _cells[id]
	return _table


# After a step: each ball's progress round the ring; hand over the ones past the rail's
# end whose velocity changed by gravity alone (touching nothing). A ball handed over is
# removed then, or with _to_first_pin once it has met a pin.
func _follow(dt: float) -> void:
	var sweep := deg_to_rad(absf(_level.rail_end_deg - _level.rail_start_deg))
	var past := sweep + deg_to_rad(RailExitTable.EXIT_MARGIN_DEG)
	var sense := -1.0 if _level.rail_end_deg < _level.rail_start_deg else 1.0
	var free_dv := _world.gravity * dt
	var sample := _step % PachinkoShotChunk.SAMPLE_EVERY == 0
	var ids := _world.get_ids()
	var pos := _world.get_positions()
	var vel := _world.get_velocities()
	var done := PackedInt32Array()
	for k in ids.size():
		var id := ids[k]
		var q := _level_of[id]
		if _handed[id] != 0:
			continue
		var angle := (pos[k] - _centre).angle()
		_travelled[id] += wrapf(angle - _last_angle[id], -PI, PI) * sense
		_last_angle[id] = angle
		if sample:
			_sample(id, pos[k])
		var free := (vel[k] - _last_vel[id] - free_dv).length() < RailExitTable.FREE_FLIGHT_EPS
		_last_vel[id] = vel[k]
		if _travelled[id] > past and free:
			_table.fate[q] = RailExitTable.Fate.EXIT
			_table.exit_pos[q] = pos[k]
			_table.exit_vel[q] = vel[k]
			_table.exit_steps[q] = _step
			_table.steps[q] = _step
			_handed[id] = 1
			if _met_pin[id] != 0 or not _to_first_pin:
				done.append(id)
	if not done.is_empty():
		_world.remove_balls(done)


# Adds the density cell of `p` to ball `id`'s list (the same cells as
# PachinkoShotChunk.cell_of, worked out here to stay off other objects).
func _sample(id: int, p: Vector2) -> void:
	var cx := int(p.x / AnalysisPlan.DENSITY_CELL)
	var cy := int(p.y / AnalysisPlan.DENSITY_CELL)
	var cols := maxi(ceili(_board_size.x / AnalysisPlan.DENSITY_CELL), 1)
	var rows := maxi(ceili(_board_size.y / AnalysisPlan.DENSITY_CELL), 1)
	if p.x >= 0.0 and p.y >= 0.0 and cx < cols and cy < rows:
		_cells[id].append(cy * cols + cx)


func _on_zone(ball_id: int, zone_index: int) -> void:
	if zone_index != 0:
		return
	var q := _level_of[ball_id]
	_table.fate[q] = RailExitTable.Fate.RETURNED
	_table.steps[q] = _step
	_world.remove_ball(ball_id)


# Drained or pocketed before the hand-over (a weak shot that drops beside the rail never
# gets far enough past its end): the shot is simulated in full.
func _on_gone(ball_id: int) -> void:
	if _handed[ball_id] == 0:
		_table.fate[_level_of[ball_id]] = RailExitTable.Fate.FULL


# The first pin a ball meets is where its power aimed it (handed over or not).
func _on_pin_hit(ball_id: int, pin_index: int, _impact_speed: float) -> void:
	if _met_pin[ball_id] != 0 or pin_index >= _level.pins.size():
		return
	_met_pin[ball_id] = 1
	_table.entry_x[_level_of[ball_id]] = _level.pins[pin_index].x
	if _handed[ball_id] != 0:
		_world.remove_ball(ball_id)


func _on_pocketed(ball_id: int, _pocket_id: int) -> void:
	_on_gone(ball_id)
