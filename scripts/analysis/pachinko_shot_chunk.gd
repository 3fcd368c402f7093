class_name PachinkoShotChunk
extends RefCounted
## Runs one chunk of an analysis: its shots, fired into one fresh world on the calling
## thread, each ball followed until it is paid, drained, rolled back or stuck. The balls
## pass through each other (BallWorld.ball_contacts off), so many fly at once and each
## behaves as if alone; the plan alone decides every power (AnalysisPlan.chunk_levels).
## A played run fires its chunks with PlayedShotChunk instead.
##
## Two shortcuts that change no outcome: a shot starts where RailExitTable says its power
## leaves the rail (the climb is the same for every shot of that power), and a ball whose
## energy can no longer lift it to any pocket's special pin is counted as drained at once
## (the gutter takes it in the end; no contact adds energy except the pins' small minimum
## horizontal speed and the game's nudge, both inside HOPELESS_MARGIN).

## Density samples are taken every this many steps (each ball's cell, once).
const SAMPLE_EVERY := 2
## Hopeless balls are looked for every this many steps.
const HOPELESS_EVERY := 4
## Stuck balls and the cancel flag are checked every this many steps.
const CHECK_EVERY := 60
## Height (px) a ball may still gain beyond its energy: the pins' minimum horizontal speed,
## the game's nudge for a resting ball, and the integrator's rounding.
const HOPELESS_MARGIN := 8.0

## The chunk's figures (its ledger's tally).
var tally: AnalysisTally
## Set before run() to time the chunk's stages into it (AnalysisProfile); null: untimed.
var profile: AnalysisProfile = null

var _ledger: ShotLedger
var _plan: AnalysisPlan
var _table: RailExitTable
var _world: BallWorld
var _launch: LaunchTable
## A ball whose highest reachable centre lies below this y can reach no special pin.
var _hopeless_y := -INF
## Per ball id (ids count up from 0 in a fresh world): 1 once it is known to be out of
## the rail (the energy test applies).
var _in_field := PackedByteArray()
## Per ball id: the power band whose first pin it still has to record (the climb handed it
## over before it met one, see RailExitTable.to_first_pin), or -1.
var _entry_band := PackedInt32Array()


## `launch` is LaunchCalibration.table(plan.level), measured once beforehand on the
## calling thread (its cache is not shared safely between threads). `table` holds the
## rail climbs of every power level the chunk uses (null: every shot is simulated in full).
func _init(plan: AnalysisPlan, launch: LaunchTable, table: RailExitTable = null) -> void:
	_plan = plan
	_launch = launch
	_table = table
	# The level's pockets and then the bonus pockets (shut unless the plan holds them open).
	_ledger = ShotLedger.new(plan)
	tally = _ledger.tally
	_hopeless_y = hopeless_line(plan.level)


## The y below which a ball's highest reachable point means it can touch no special pin
## (-INF when the board has none: no ball out of the rail can be paid).
static func hopeless_line(level: BoardLevel) -> float:
	var line := -INF
	for k in mini(level.pins.size(), level.pin_special.size()):
		if level.pin_special[k] != 0:
			line = maxf(line, level.pins[k].y + level.pin_radius + level.ball_radius)
	line = maxf(line, BonusGeometry.lowest_catch_y(level) + level.pin_radius + level.ball_radius)
	return line + HOPELESS_MARGIN if line > -INF else -INF


## The density cell of a board point, or -1 outside the board.
static func cell_of(p: Vector2, board_size: Vector2) -> int:
	var cols := maxi(ceili(board_size.x / AnalysisPlan.DENSITY_CELL), 1)
	var rows := maxi(ceili(board_size.y / AnalysisPlan.DENSITY_CELL), 1)
	var cx := int(p.x / AnalysisPlan.DENSITY_CELL)
	var cy := int(p.y / AnalysisPlan.DENSITY_CELL)
	if p.x < 0.0 or p.y < 0.0 or cx >= cols or cy >= rows:
		return -1
	return cy * cols + cx


## Fires the shots of chunk `index`. `cancelled` is polled now and then; when it returns
## true the run stops early and returns false (the tally then holds only finished shots).
func run(index: int, cancelled: Callable = Callable()) -> bool:
	var prof := profile != null
	var mark := Time.get_ticks_usec() if prof else 0
	var levels := _plan.chunk_levels(index)
	_ledger.open()
	var in_flight := _plan.in_flight
	_world = chunk_world(_plan, false, _on_pocketed, _on_drained, _on_zone)
	if _table != null and not _table.to_first_pin:
		_world.pin_hit.connect(_on_pin_hit)
	var dt := 1.0 / maxf(_world.tuning.fixed_hz, 1.0)
	var max_steps := int(AnalysisPlan.MAX_BALL_SECONDS / dt)
	var hopeless_ok := _world.gravity.x == 0.0 and _world.gravity.y > 0.0
	var fired := 0
	var step := 0
	if prof:
		mark = _lap(AnalysisProfile.Stage.CHUNK_SETUP, mark)
	while fired < levels.size() or _world.ball_count() > 0:
		while fired < levels.size() and _world.ball_count() < in_flight:
			_fire(levels[fired], step)
			fired += 1
		tally.ball_steps += _world.ball_count()
		if prof:
			mark = _lap(AnalysisProfile.Stage.FIRE, mark)
		_world.step(dt)
		step += 1
		if prof:
			mark = _lap(AnalysisProfile.Stage.STEP, mark)
		if step % SAMPLE_EVERY == 0:
			_ledger.sample(_world.get_positions())
			if prof:
				mark = _lap(AnalysisProfile.Stage.SAMPLE, mark)
		if hopeless_ok and step % HOPELESS_EVERY == 0:
			_drop_hopeless()
			if prof:
				mark = _lap(AnalysisProfile.Stage.HOPELESS, mark)
		if step % CHECK_EVERY == 0:
			_ledger.drop_stuck(_world, step - max_steps)
			if prof:
				mark = _lap(AnalysisProfile.Stage.CHECK, mark)
			if cancelled.is_valid() and cancelled.call():
				_ledger.close()
				return false
	tally.steps += step
	_ledger.close()
	_world = null
	if prof:
		profile.chunks += 1
		profile.chunk_steps += step
	return true


## A chunk's world for `plan`'s board, on the calling thread, ball contacts on or off, its
## bonus parts open if the plan holds them open, its catches, drains and zone entries
## reported to the three handlers.
static func chunk_world(
	plan: AnalysisPlan, contacts: bool, on_caught: Callable, on_drained: Callable, on_zone: Callable
) -> BallWorld:
	var world := BoardWorldFactory.build(plan.level)
	world.threads = 1
	world.ball_contacts = contacts
	if plan.bonus_open:
		open_bonus_parts(world, plan.level)
	world.ball_captured.connect(on_caught)
	world.ball_drained.connect(on_drained)
	world.ball_entered_zone.connect(on_zone)
	return world


## Lifts every attacker lid and spreads every tulip's wings in `world`, built for `level`
## (BoardWorldFactory builds them shut).
static func open_bonus_parts(world: BallWorld, level: BoardLevel) -> void:
	var parts := BonusGeometry.wall_plan(level)
	for wall in parts.size():
		var part: BonusGeometry.Part = parts[wall]["part"]
		world.shapes.set_wall_enabled(wall, BonusGeometry.part_solid(part, true))
	for gate in world.shapes.gate_count():
		world.shapes.set_gate_open(gate, true, true)


# Adds the time since `mark` to `stage` of the profile; returns the time now.
func _lap(stage: AnalysisProfile.Stage, mark: int) -> int:
	var now := Time.get_ticks_usec()
	profile.add_usec(stage, now - mark)
	return now


# One shot of power level `q` at step `step`: from the rail table when it knows the climb.
func _fire(q: int, step: int) -> void:
	var band := AnalysisPlan.band_of(AnalysisPlan.power_of(q))
	var fate := _table.fate[q] if _table != null else RailExitTable.Fate.UNKNOWN
	if fate == RailExitTable.Fate.RETURNED or fate == RailExitTable.Fate.EXIT:
		_ledger.add_samples(_table.samples[q])
	var entry_later := _table != null and _table.entry_after_exit(q)
	if _table != null and not entry_later:
		tally.record_entry(band, _table.entry_x[q])
	if fate == RailExitTable.Fate.RETURNED:
		tally.record(band, AnalysisTally.Outcome.RETURNED)
		return
	var id := -1
	if fate == RailExitTable.Fate.EXIT:
		id = _world.spawn_ball(_table.exit_pos[q], _table.exit_vel[q], _plan.level.ball_radius)
		step -= _table.exit_steps[q]
	else:
		var speed := _launch.launch_speed(AnalysisPlan.power_of(q))
		var launch := LaunchRail.launch_position(_plan.level)
		var direction := LaunchRail.launch_direction(_plan.level)
		id = _world.spawn_ball(launch, direction * speed, _plan.level.ball_radius)
	_ledger.fired(id, band, step)
	_in_field.resize(id + 1)
	_in_field[id] = 1 if fate == RailExitTable.Fate.EXIT else 0
	_entry_band.resize(id + 1)
	_entry_band[id] = band if entry_later else -1


# Balls out of the rail whose energy cannot lift them to any special pin: drained.
func _drop_hopeless() -> void:
	var ids := _world.get_ids()
	var pos := _world.get_positions()
	var vel := _world.get_velocities()
	var two_g := 2.0 * _world.gravity.y
	var dropped := PackedInt32Array()
	for k in ids.size():
		var id := ids[k]
		if _in_field[id] != 0 and pos[k].y - vel[k].length_squared() / two_g > _hopeless_y:
			dropped.append(id)
			_ledger.record(id, AnalysisTally.Outcome.DRAINED)
	if not dropped.is_empty():
		_world.remove_balls(dropped)


# The first pin a ball handed over before meeting one meets: its shot's entry (the pins of
# the level only, as RailClimber counts them).
func _on_pin_hit(ball_id: int, pin_index: int, _impact_speed: float) -> void:
	var band := _entry_band[ball_id]
	if band < 0 or pin_index >= _plan.level.pins.size():
		return
	_entry_band[ball_id] = -1
	tally.record_entry(band, _plan.level.pins[pin_index].x)


func _on_pocketed(ball_id: int, pocket_id: int) -> void:
	_ledger.record(ball_id, AnalysisTally.Outcome.POCKETED, pocket_id)


func _on_drained(ball_id: int) -> void:
	_ledger.record(ball_id, AnalysisTally.Outcome.DRAINED)


# Zone 0 is the rail's return zone: a weak shot rolled back into the cup.
func _on_zone(ball_id: int, zone_index: int) -> void:
	if zone_index != 0:
		return
	_world.remove_ball(ball_id)
	_ledger.record(ball_id, AnalysisTally.Outcome.RETURNED)
