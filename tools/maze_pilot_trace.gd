extends SceneTree
## Plays one maze board in hard mode with the autoplay pilot and prints how each seed ends:
## won, a fall (which hole, where, in which pilot phase, how close the nearest ball came to
## a hole before), or a timeout (the phase, plans made, balls in the goal), plus a line per
## `--every` seconds with the pilot's phase and the balls' cells. For finding out why the
## pilot loses a board:
##   tools/godot.sh --headless --path . -s res://tools/maze_pilot_trace.gd -- --board=the_deep
## Options after `--`: `--board=ID` or `--generated=COLS,ROWS,HOLES,DIFFICULTY,SEED` (a
## maze from the generator), `--seeds=A-B` (default 1-5), `--every=S` (a progress line
## every S seconds, 0 for none; default 0), `--easy`.

const SECONDS := 120.0
const PHASES := ["PLAN", "MOVE", "HERD", "LEAD"]


func _initialize() -> void:
	var args := {}
	for arg in OS.get_cmdline_user_args():
		var parts := arg.trim_prefix("--").split("=", true, 1)
		args[parts[0]] = parts[1] if parts.size() > 1 else "1"
	var level := _level(args)
	if level == null:
		quit(1)
		return
	var seeds: PackedStringArray = String(args.get("seeds", "1-5")).split("-")
	var first := seeds[0].to_int()
	var last := seeds[seeds.size() - 1].to_int()
	for s in range(first, last + 1):
		_trace(level, s, not args.has("easy"), float(args.get("every", "0")))
	quit(0)


# The board named by --board=ID, or a maze made by the generator from
# --generated=cols,rows,holes,difficulty,seed.
func _level(args: Dictionary) -> BoardLevel:
	if args.has("generated"):
		var v: PackedStringArray = String(args["generated"]).split(",")
		var settings := MazeGenSettings.new()
		var values := {"cols": v[0].to_int(), "rows": v[1].to_int(), "holes": v[2].to_int()}
		values["difficulty"] = v[3].to_float()
		values["seed"] = v[4].to_int()
		settings.read(values)
		var made := MazeGenerator.generate(settings)
		if made.has("error"):
			printerr("maze_pilot_trace: %s" % made["error"])
		return made.get("level")
	var loaded := BoardLoader.load_board("res://levels/maze/%s.board" % args.get("board", ""))
	if loaded.level == null:
		printerr("maze_pilot_trace: %s" % loaded.error)
	return loaded.level


func _trace(level: BoardLevel, rng_seed: int, hard: bool, every: float) -> void:
	var rules := MazeRules.new(level, hard)
	var rng := RandomNumberGenerator.new()
	rng.seed = rng_seed
	var pilot := MazePilot.new(level, hard, rng, rules.step_seconds())
	rules.start()
	var limit := ceili(SECONDS / rules.step_seconds())
	var stats := _TraceStats.new()
	var next_line := every
	var frames := 0
	while frames < limit and rules.is_playing():
		var world := rules.world
		var positions := world.get_positions()
		stats.note_gap(_hole_gap(level, positions), pilot, rules.elapsed, positions)
		rules.set_tilt(pilot.decide(positions, world.get_velocities()))
		stats.note_phase(pilot.phase, rules.step_seconds())
		rules.step()
		frames += 1
		stats.note_move(pilot)
		if every > 0.0 and rules.elapsed >= next_line:
			next_line += every
			print(_progress_line(rules, pilot, positions))
	print(
		(
			"seed %d: %s; phase %s, plans %d, corrections %d, closest edge gap %.1f px (%s), in goal %d; %s"
			% [
				rng_seed,
				_outcome(rules, level),
				PHASES[pilot.phase],
				pilot.plans_made,
				pilot.corrections,
				stats.closest,
				stats.closest_at,
				rules.balls_in_goal,
				", ".join(stats.lines()),
			]
		)
	)


func _progress_line(rules: MazeRules, pilot: MazePilot, positions: PackedVector2Array) -> String:
	return (
		"  %5.1f s %s plans %d in goal %d cells %s"
		% [
			rules.elapsed,
			PHASES[pilot.phase],
			pilot.plans_made,
			rules.balls_in_goal,
			pilot.planner.cells_of(positions) if pilot.planner != null else [],
		]
	)


func _outcome(rules: MazeRules, level: BoardLevel) -> String:
	if rules.state == MazeRules.State.WON:
		return "WON %.1f s" % rules.elapsed
	if rules.state == MazeRules.State.LOST:
		return (
			"FELL in hole %d at %.1f s (%s)"
			% [rules.lost_hole, rules.elapsed, level.holes[rules.lost_hole]]
		)
	return "TIMEOUT"


# What one traced game did: the closest call to a hole, seconds per pilot phase, and each
# kind of move (slide, step) with its count, mean time and timeouts.
class _TraceStats:
	var closest := INF
	var closest_at := ""
	var phase_time := {}
	var move_stats := {}
	var _last_key := ""
	var _last_kind := ""
	var _last_time := 0.0

	func note_gap(gap: float, pilot: MazePilot, at: float, positions: PackedVector2Array) -> void:
		if gap >= closest:
			return
		closest = gap
		closest_at = "%s at %.1f s" % [PHASES[pilot.phase], at]
		if pilot.phase == MazePilot.Phase.MOVE:
			closest_at += " move %d, balls %s" % [pilot.planner.moves[pilot._move], positions]

	func note_phase(phase: int, seconds: float) -> void:
		phase_time[phase] = phase_time.get(phase, 0.0) + seconds

	func note_move(pilot: MazePilot) -> void:
		var key := "%d/%d/%d" % [pilot.plans_made, pilot._move, pilot.phase]
		if key != _last_key:
			if _last_kind != "":
				_add_stat(_last_kind, _last_time)
			_last_key = key
			_last_kind = ""
			if pilot.phase == MazePilot.Phase.MOVE:
				var move: int = pilot.planner.moves[pilot._move]
				_last_kind = "step" if pilot.grid.is_step(move) else "slide"
		_last_time = pilot._move_time

	func lines() -> Array:
		var out := []
		for p: int in phase_time:
			out.append("%s %.0f s" % [PHASES[p], phase_time[p]])
		for kind: String in move_stats:
			var st: Array = move_stats[kind]
			out.append(
				"%s x%d avg %.2f s, %d timed out" % [kind, st[0], st[1] / maxf(1.0, st[0]), st[2]]
			)
		return out

	func _add_stat(kind: String, seconds: float) -> void:
		var st: Array = move_stats.get(kind, [0, 0.0, 0])
		st[0] += 1
		st[1] += seconds
		if seconds > MazePilot.MOVE_TIMEOUT:
			st[2] += 1
		move_stats[kind] = st


# Smallest gap between a ball's centre and a hole's rim, px (negative: over the hole).
func _hole_gap(level: BoardLevel, positions: PackedVector2Array) -> float:
	var gap := INF
	for p in positions:
		for h in level.holes:
			gap = minf(gap, p.distance_to(h) - level.hole_radius)
	return gap
