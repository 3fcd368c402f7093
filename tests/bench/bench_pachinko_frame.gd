extends SceneTree
## Pachinko frame benchmark: the classic board with 200 balls in play, simulated and drawn.
## Each measured frame runs one 60 fps frame of simulation (PachinkoRules.advance, two
## 120 Hz physics steps with every contact and event) and the board view's ball layer
## draw (all balls in one batch: GDScript building the draw commands). Headless, the
## rendering server is a dummy: GPU work and presenting the frame are NOT measured.
## Writes build/bench/pachinko_frame.json.

const CLASSIC := "res://levels/pachinko/classic.board"
const BOARD_VIEW := "res://scenes/pachinko/board/board_view.tscn"
const BALLS := 200
const WARMUP_FRAMES := 60
const FRAMES := 300
const FRAME_SECONDS := 1.0 / 60.0
const BUDGET_MS := 1000.0 / 60.0

var _rules: PachinkoRules
var _view: Node2D
var _balls: Node2D
var _rng := RandomNumberGenerator.new()
var _frame := 0
var _sim_ms := PackedFloat64Array()
var _draw_ms := PackedFloat64Array()
var _counts := PackedInt32Array()
var _started := false


func _initialize() -> void:
	_rng.seed = 1
	var loaded := BoardLoader.load_board(CLASSIC)
	if loaded.level == null:
		printerr("bench_pachinko_frame: %s" % loaded.error)
		quit(1)
		return
	var level := loaded.level.duplicate(true) as BoardLevel
	level.cup_start_balls = 100000
	_rules = PachinkoRules.new(level, 1)
	_rules.start_game()
	_view = (load(BOARD_VIEW) as PackedScene).instantiate() as Node2D
	root.add_child.call_deferred(_view)


func _process(_delta: float) -> bool:
	if not _started:
		# The view's layers are ready once the tree has taken it in.
		if _view == null or not _view.is_node_ready():
			return false
		_view.call("bind", _rules)
		_balls = _view.get_node("Balls") as Node2D
		_started = true
	# The previous frame's draw has run by now (queue_redraw is processed between frames).
	if _frame > WARMUP_FRAMES:
		_draw_ms.append(int(_balls.get("last_draw_usec")) / 1000.0)
	_top_up()
	var t0 := Time.get_ticks_usec()
	_rules.advance(FRAME_SECONDS)
	var t1 := Time.get_ticks_usec()
	if _frame >= WARMUP_FRAMES:
		_sim_ms.append((t1 - t0) / 1000.0)
		_counts.append(_rules.world.ball_count())
	_balls.queue_redraw()
	_frame += 1
	if _frame > WARMUP_FRAMES + FRAMES:
		_finish()
		return true
	return false


# Keeps 200 balls in play: each ball that leaves is replaced by a new shot, dropped in
# across the upper field (a player cannot fire fast enough to keep 200 up by hand).
func _top_up() -> void:
	var level := _rules.level
	var missing := BALLS - _rules.world.ball_count()
	for i in missing:
		var id := _rules.fire(_rng.randf_range(20.0, 100.0))
		if id < 0:
			break
		var angle := _rng.randf_range(-2.4, -0.7)
		var r := _rng.randf_range(0.2, 0.85) * level.ring_radius
		var at := level.ring_center + Vector2(cos(angle), sin(angle)) * r
		_rules.world.set_ball_position(id, at)
		_rules.world.set_ball_velocity(id, Vector2(_rng.randf_range(-60, 60), 0))


func _finish() -> void:
	var sim := _stats(_sim_ms)
	var draw := _stats(_draw_ms)
	var total_mean: float = sim["mean"] + draw["mean"]
	var total_p95: float = sim["p95"] + draw["p95"]
	var balls := _stats_int(_counts)
	var speed_sum := 0.0
	for v in _rules.world.get_velocities():
		speed_sum += v.length()
	var mean_speed := speed_sum / maxf(_rules.world.ball_count(), 1.0)
	var result := {
		"bench": "pachinko_frame",
		"board": _rules.level.board_id,
		"balls_target": BALLS,
		"balls_in_play_mean": balls,
		"balls_drawn_last_frame": int(_balls.get("last_drawn")),
		"mean_ball_speed_px_s": snappedf(mean_speed, 0.1),
		"frames": _sim_ms.size(),
		"steps_per_frame": roundi(_rules.world.tuning.fixed_hz * FRAME_SECONDS),
		"sim_ms": sim,
		"draw_prep_ms": draw,
		"frame_ms_mean": snappedf(total_mean, 0.001),
		"frame_ms_p95": snappedf(total_p95, 0.001),
		"budget_ms": snappedf(BUDGET_MS, 0.001),
		"within_budget": total_p95 < BUDGET_MS,
		"measured": "PachinkoRules.advance (physics + rules) and the ball layer's _draw",
		"not_measured": "GPU rendering and presenting (headless dummy renderer)",
	}
	print("pachinko frame bench: classic board, %.0f balls in play on average" % balls)
	print("  simulation  mean %.2f ms  p95 %.2f ms" % [sim["mean"], sim["p95"]])
	print("  draw prep   mean %.2f ms  p95 %.2f ms" % [draw["mean"], draw["p95"]])
	print(
		(
			"  frame       mean %.2f ms  p95 %.2f ms  budget %.1f ms  %s"
			% [total_mean, total_p95, BUDGET_MS, "OK" if total_p95 < BUDGET_MS else "OVER"]
		)
	)
	DirAccess.make_dir_recursive_absolute(ProjectSettings.globalize_path("res://build/bench"))
	var file := FileAccess.open("res://build/bench/pachinko_frame.json", FileAccess.WRITE)
	if file != null:
		file.store_string(JSON.stringify(result, "  ") + "\n")
	_view.queue_free()
	quit(0)


func _stats(values: PackedFloat64Array) -> Dictionary:
	if values.is_empty():
		return {"mean": 0.0, "p95": 0.0, "max": 0.0}
	var sorted := values.duplicate()
	sorted.sort()
	var total := 0.0
	for v in sorted:
		total += v
	return {
		"mean": snappedf(total / sorted.size(), 0.001),
		"p95": snappedf(sorted[int(sorted.size() * 0.95) - 1], 0.001),
		"max": snappedf(sorted[sorted.size() - 1], 0.001),
	}


func _stats_int(values: PackedInt32Array) -> float:
	var total := 0
	for v in values:
		total += v
	return float(total) / maxf(values.size(), 1.0)
