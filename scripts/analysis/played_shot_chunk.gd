class_name PlayedShotChunk
extends RefCounted
## Runs one chunk of an analysis as a player plays it: the chunk's shots are fired one at a
## time from the launcher, at the autoplay's pace (a pause drawn evenly from
## PachinkoAutoplay.MIN_GAP to MAX_GAP after each), into one world with ball contacts on,
## so each ball flies among the balls still in play as it would in the game and may be
## knocked into or out of a pocket. The rules' upkeep applies as in the game: a ball wedged
## in a pocket's cup counts as caught (PocketJam), a resting ball gets a nudge, and the
## launcher waits while a ball rolls back down the rail.
##
## Why not many balls flying through each other (PachinkoShotChunk): on Classic about one
## shot in thirty ends elsewhere when it meets the balls in play, more often out of a
## pocket than into one, and the return a player gets came out about 0.07 under the
## contact-free figure (measured shot by shot against the autoplay, 3 seeds of 900 s).
##
## Each chunk starts with an empty field, as a game does. Its powers are the plan's
## (AnalysisPlan.chunk_levels: the same as a contact-free run); the pauses and the nudges
## come from an RNG of the chunk's own (AnalysisPlan.chunk_seed).

## The chunk's figures (its ledger's tally).
var tally: AnalysisTally

var _ledger: ShotLedger
var _plan: AnalysisPlan
var _table: RailExitTable
var _world: BallWorld
var _launch: LaunchTable
var _upkeep := BallUpkeep.new()


## `launch` is LaunchCalibration.table(plan.level); `table` the rail climbs, read only for
## where each power first meets a pin (null: no entry figures).
func _init(plan: AnalysisPlan, launch: LaunchTable, table: RailExitTable = null) -> void:
	_plan = plan
	_launch = launch
	_table = table
	_ledger = ShotLedger.new(plan)
	tally = _ledger.tally


## Fires the shots of chunk `index`. `cancelled` is polled now and then; when it returns
## true the run stops early and returns false (the tally then holds only finished shots).
func run(index: int, cancelled: Callable = Callable()) -> bool:
	var levels := _plan.chunk_levels(index)
	_ledger.open()
	_world = PachinkoShotChunk.chunk_world(_plan, true, _on_pocketed, _on_drained, _on_zone)
	var pace := RandomNumberGenerator.new()
	pace.seed = _plan.chunk_seed(index)
	var dt := 1.0 / maxf(_world.tuning.fixed_hz, 1.0)
	var max_steps := int(AnalysisPlan.MAX_BALL_SECONDS / dt)
	var frame := PachinkoAutoplay.FRAME_SECONDS
	var fired := 0
	var step := 0
	var clock := 0.0
	var next_shot := 0.0
	var next_check := PachinkoShotChunk.CHECK_EVERY
	while fired < levels.size() or _world.ball_count() > 0:
		clock += frame
		if fired < levels.size() and clock >= next_shot and not _rail_blocked():
			_fire(levels[fired], step)
			fired += 1
			next_shot = clock + pace.randf_range(PachinkoAutoplay.MIN_GAP, PachinkoAutoplay.MAX_GAP)
		var ran := _world.advance(frame)
		tally.ball_steps += _world.ball_count() * ran
		step += ran
		if ran > 0:
			_ledger.sample(_world.get_positions())
			_upkeep_after(ran * dt, pace)
		if step >= next_check:
			next_check += PachinkoShotChunk.CHECK_EVERY
			for id: int in _ledger.drop_stuck(_world, step - max_steps):
				_upkeep.forget(id)
			if cancelled.is_valid() and cancelled.call():
				_ledger.close()
				return false
	tally.steps += step
	_ledger.close()
	_world = null
	return true


func _rail_blocked() -> bool:
	return RailTraffic.ball_coming_down(
		_plan.level, _world.get_positions(), _world.get_velocities()
	)


# One shot of power level `q`, from the launcher, as the rules fire it.
func _fire(q: int, step: int) -> void:
	var power := AnalysisPlan.power_of(q)
	var band := AnalysisPlan.band_of(power)
	if _table != null:
		tally.record_entry(band, _table.entry_x[q])
	var speed := _launch.launch_speed(power)
	var direction := LaunchRail.launch_direction(_plan.level)
	var at := LaunchRail.launch_position(_plan.level)
	var id := _world.spawn_ball(at, direction * speed, _plan.level.ball_radius)
	_ledger.fired(id, band, step)


# The rules' upkeep between frames: wedged balls are caught, resting ones nudged.
func _upkeep_after(seconds: float, rng: RandomNumberGenerator) -> void:
	var in_play := Array(_world.get_ids())
	var jammed := _upkeep.jammed(_plan.level, _world, in_play, seconds)
	for id: int in jammed:
		var pocket: int = jammed[id]
		_world.remove_ball(id)
		_upkeep.forget(id)
		_on_pocketed(id, pocket)
	if not jammed.is_empty():
		in_play = Array(_world.get_ids())
	_upkeep.nudge_resting(_world, in_play, seconds, rng)


func _on_pocketed(ball_id: int, pocket_id: int) -> void:
	_upkeep.forget(ball_id)
	_ledger.record(ball_id, AnalysisTally.Outcome.POCKETED, pocket_id)


func _on_drained(ball_id: int) -> void:
	_upkeep.forget(ball_id)
	_ledger.record(ball_id, AnalysisTally.Outcome.DRAINED)


# Zone 0 is the rail's return zone: a shot rolled back into the cup.
func _on_zone(ball_id: int, zone_index: int) -> void:
	if zone_index != 0:
		return
	_world.remove_ball(ball_id)
	_upkeep.forget(ball_id)
	_ledger.record(ball_id, AnalysisTally.Outcome.RETURNED)
