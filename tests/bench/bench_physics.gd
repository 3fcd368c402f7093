extends SceneTree
## `make bench`: BallWorld against Godot's GodotPhysics2D (PhysicsServer2D) on the same
## scenes, ball-steps per second, tunnels and escapes counted by an independent swept check;
## the zoning-versus-brute-force ratio and the scale sweeps. Prints a table and the seconds
## each phase took, and writes build/bench/physics.json. Both sides run on every core (our
## per-ball stages in worker lanes, GodotPhysics2D with its worker pool), so speeds are
## wall-clock ball-steps per second, three side-by-side rounds per scenario; the JSON adds
## the cores used ("threads"), S1's speed on them over one thread ("thread_scaling") and
## whether 1, 2 and 4 threads leave identical states after S1, S2, S4 and S5
## ("threads_identical"). S5 (1,000 balls flowing through the lattice past 40 windmills, at
## the game's 120 Hz, blade tips up to the top ball speed) is ours alone: GodotPhysics2D
## has no scene of turning wheels here to compare; its row has our speed and the tunnels
## through pins, walls and blades ("blade_tunnels", counted by BladeCheck).
##
## Every Godot-side job (a timing run or a check run) stops at JOB_BUDGET_S of CPU time
## even short of its steps: GodotPhysics2D's cast-shape CCD costs about 2 s a step on S3,
## which alone used to take over four minutes. Rates are over the steps actually run, and
## the JSON and the table say how many that was (godot_steps_run, godot_steps_checked).

const BenchScenes := preload("res://tests/bench/physics/bench_scenes.gd")
const SweptCheck := preload("res://tests/bench/physics/swept_check.gd")
const GodotSide := preload("res://tests/bench/physics/godot_side.gd")
const OursRunner := preload("res://tests/bench/physics/ours_runner.gd")
const CpuClock := preload("res://tests/bench/physics/cpu_clock.gd")
const TimingRounds := preload("res://tests/bench/physics/timing_rounds.gd")
const FloorKernel := preload("res://tests/bench/physics/floor_kernel.gd")
const BenchTable := preload("res://tests/bench/physics/bench_table.gd")
const PhaseClock := preload("res://tests/bench/physics/phase_clock.gd")

const OUT_PATH := "res://build/bench/physics.json"
## Engine physics ticks run this many times faster than the scene's rate, and time_scale
## slows them back down: each tick still integrates 1 / hz, but ticks run back to back.
const SPEEDUP := 100
const WARMUP := OursRunner.WARMUP
## CPU seconds one Godot-side job may use, counted from building its scene.
const JOB_BUDGET_S := 20.0
## Most steps the Godot-side check run of the fast scene (S3) covers (see _job_over()).
const GODOT_CHECK_CAP := 12
## A timing run stops for the budget only once its timed span is this long: the CPU clock
## ticks in 10 ms, so a shorter span would be mostly rounding.
const MIN_TIMED_S := 1.0
## Side-by-side timing rounds per scenario (ours, then Godot's); see TimingRounds. A scenario
## whose Godot timing run hit the budget gets no more rounds.
const TIMING_ROUNDS := 3
## Steps each thread-count run covers before its state hash is compared.
const THREAD_CHECK_STEPS := 60
## Timed steps of each one-thread and all-threads run of the S1 scaling figure.
const THREAD_SCALING_STEPS := 300
## Scenarios timed on our side only (no GodotPhysics2D scene, no floor).
const OURS_ONLY: Array[String] = ["S5"]

## name, mode, pin pitch, balls, hz, checked steps, timed steps. Timing runs are longer than
## check runs so that each side's timed span lasts a second or more on the 10 ms clock.
var _specs: Array = [
	["S1", "flow", 24.0, 1000, 240.0, 240, 600],
	["S2", "pile", 24.0, 3000, 240.0, 90, 180],
	["S3", "fast", 12.0, 500, 60.0, 60, 300],
	["S4", "maze", 0.0, 1000, 120.0, 240, 480],
	["S5", "windmills", 24.0, 1000, 120.0, 240, 600],
]

var _results := {}
var _scale := {}
var _zoned_vs_brute := 0.0
var _threads := 1
var _threads_identical := false
var _thread_hashes := {}
var _thread_scaling := {}
## Scenario → CPU µs per step of each stage on one thread, and wall µs on every core (see
## OursRunner.stage_breakdown()).
var _stages := {}
var _stages_all := {}
## Each phase's CPU and wall seconds, in the order the phases ran.
var _clock := PhaseClock.new()
## Scenario name → its FloorKernel (S3 has none: its balls need 17 substeps a step to stay
## tunnel-free, which a floor without substeps would leave out).
var _floors := {}
var _jobs: Array = []
var _job := {}
var _want_job := false
var _side: GodotSide
var _check: SweptCheck
var _rng := RandomNumberGenerator.new()
var _prev := PackedVector2Array()
var _step_i := 0
var _cpu0 := 0
var _wall0 := 0
var _started_usec := 0


func _initialize() -> void:
	_started_usec = Time.get_ticks_usec()
	var cpus := PhaseClock.proc_status("Cpus_allowed_list")
	print(
		(
			"bench_physics: CPUs allowed %s, processors %d, threads %s, Godot job budget %.0f s CPU"
			% [cpus, OS.get_processor_count(), PhaseClock.proc_status("Threads"), JOB_BUDGET_S]
		)
	)
	for spec: Array in _specs:
		if not _wanted(spec[0]):
			continue
		_clock.begin()
		var scene: Dictionary = BenchScenes.make(spec[0], spec[1], spec[2], spec[3], spec[4])
		var c: Dictionary = OursRunner.run(scene, spec[5], true)
		_results[spec[0]] = {
			"ours_steps_per_s": 0.0,
			"ours_steps_run": spec[6],
			"tunnels": c["tunnels"],
			"escapes": c["escapes"],
			"balls": spec[3],
			"pins": (scene["pins"] as PackedVector2Array).size(),
			"walls": (scene["walls"] as PackedVector2Array).size() / 2,
			"windmills": (scene["windmills"] as Array).size(),
			"blade_tunnels": c["blade_tunnels"],
			"hz": spec[4],
			"steps": spec[5],
			"timing_steps": spec[6],
		}
		print("  ours %s: tunnels %d, escapes %d" % [spec[0], c["tunnels"], c["escapes"]])
		_clock.end("ours %s check" % spec[0])
		if spec[0] in OURS_ONLY:
			for _round: int in TIMING_ROUNDS:
				_time_ours_round(spec, scene, _results[spec[0]])
			continue
		if spec[1] != "fast":
			_clock.begin()
			_floors[spec[0]] = FloorKernel.new(scene)
			_floors[spec[0]].prepare(spec[6])
			_clock.end("floor %s states" % spec[0])
		for _round: int in TIMING_ROUNDS:
			_jobs.append([spec, scene, false])
		_jobs.append([spec, scene, true])
	_thread_extras()
	if _wanted("S1"):
		_ours_extras()
	physics_frame.connect(_on_physics_frame)
	process_frame.connect(_on_process_frame)
	_want_job = true


## Thread keys: the cores our world uses, S1's scaling from one thread to all of them,
## and whether 1, 2 and 4 threads give the same state after S1, S2, S4 and S5.
func _thread_extras() -> void:
	_clock.begin()
	_threads = BallWorld.new().threads
	var identical := true
	for spec: Array in _specs:
		if spec[0] in ["S1", "S2", "S4", "S5"] and _wanted(spec[0]):
			var scene: Dictionary = BenchScenes.make(spec[0], spec[1], spec[2], spec[3], spec[4])
			var same: Dictionary = OursRunner.threads_identical(scene, THREAD_CHECK_STEPS)
			_thread_hashes[spec[0]] = same["hashes"]
			identical = identical and same["identical"]
	_threads_identical = identical
	print("  threads %d, identical states for 1/2/4 threads: %s" % [_threads, identical])
	_clock.end("ours thread identity")
	_clock.begin()
	for spec: Array in _specs:
		if spec[0] in ["S1", "S2", "S4", "S5"] and _wanted(spec[0]):
			var scene: Dictionary = BenchScenes.make(spec[0], spec[1], spec[2], spec[3], spec[4])
			_stages[spec[0]] = OursRunner.stage_breakdown(scene, THREAD_SCALING_STEPS / 2)
			_stages_all[spec[0]] = OursRunner.stage_breakdown(
				scene, THREAD_SCALING_STEPS / 2, OS.get_processor_count()
			)
	_clock.end("ours stage breakdown")
	if not _wanted("S1"):
		return
	_clock.begin()
	var s1: Dictionary = BenchScenes.make("S1", "flow", 24.0, 1000, 240.0)
	var floor_round := Callable()
	if _floors.has("S1"):
		floor_round = (_floors["S1"] as FloorKernel).time_round
	_thread_scaling = OursRunner.thread_scaling(
		s1, THREAD_SCALING_STEPS, TIMING_ROUNDS, floor_round
	)
	# The machine figures of the same rounds are printed with the table (BenchTable).
	print("  thread scaling (S1): %.2fx" % _thread_scaling["scaling"])
	_clock.end("ours thread scaling")


## The zoning-versus-brute-force ratio and the scale sweeps (our side only, all on S1).
func _ours_extras() -> void:
	_clock.begin()
	_zoned_vs_brute = OursRunner.zoned_vs_brute(
		BenchScenes.make("S1", "flow", 24.0, 1000, 240.0), 12
	)
	print("  zoned vs brute force (S1): %.1fx" % _zoned_vs_brute)
	_clock.end("ours zoned vs brute")
	_clock.begin()
	_scale = OursRunner.scale_sweep()
	_clock.end("ours scale sweep")


## Jobs start between frames: the engine reads the tick rate and time scale once per frame,
## so a job started inside a physics tick would run its first ticks at the last one's rate.
func _on_process_frame() -> void:
	if not _want_job:
		return
	_want_job = false
	if _jobs.is_empty():
		_finish()
		return
	var job: Array = _jobs.pop_front()
	var spec: Array = job[0]
	var scene: Dictionary = job[1]
	var row: Dictionary = _results[spec[0]]
	if not job[2]:
		if row.get("godot_budget_hit", false):
			_want_job = true
			return
		_time_ours_round(spec, scene, row)
	_job = {"spec": spec, "scene": scene}
	_clock.begin()
	_rng.seed = OursRunner.RULES_SEED
	var hz: float = spec[4]
	Engine.time_scale = SPEEDUP
	Engine.physics_ticks_per_second = int(hz * SPEEDUP)
	Engine.max_physics_steps_per_frame = 32
	_side = GodotSide.new()
	var maze: bool = spec[1] == "maze"
	var g := TuningPresets.pachinko().gravity
	if maze:
		g = MazeTilt.gravity(BenchScenes.maze_tilt(0.0), TuningPresets.maze().tilt_gravity)
	_side.build(scene, g, 1.0 / 3.0 if maze else 0.6, spec[1] == "fast")
	_check = SweptCheck.new(scene) if job[2] else null
	_prev = scene["pos"]
	_step_i = 0


## One engine physics tick: the signal comes just before each step of the Godot side.
func _on_physics_frame() -> void:
	if _side == null:
		return
	var done := _step_i  # steps the engine has run on this job so far
	_step_i += 1
	var spec: Array = _job["spec"]
	var mode: String = spec[1]
	var hz: float = spec[4]
	if done == WARMUP and _check == null:
		_cpu0 = CpuClock.usec()
		_wall0 = Time.get_ticks_usec()
	if _check != null:
		var pos: PackedVector2Array = _side.positions()
		if done > 0:
			var skip := PackedByteArray()
			skip.resize(pos.size())
			skip.fill(0)
			_check.check(_prev, pos, skip)
			OursRunner.harness_rules(mode, done, pos, _rng, _side, hz)
		_prev = pos
	elif done > 0 and OursRunner.rules_due(mode, done):
		var pos := PackedVector2Array() if mode == "maze" else _side.positions()
		OursRunner.harness_rules(mode, done, pos, _rng, _side, hz)
	if _job_over(done):
		_end_job(done)


## Whether the job stops after `done` steps: all its steps ran, or it has used its budget
## (a timing run also needs a timed span of MIN_TIMED_S past the warm-up).
func _job_over(done: int) -> bool:
	var spec: Array = _job["spec"]
	if done >= (spec[5] if _check != null else spec[6]):
		return true
	# One GodotPhysics2D step of S3's check run can take minutes once balls have escaped
	# (cast-shape CCD, and the swept check over their long paths), and a budget can only
	# stop a job between steps: the check there covers its first GODOT_CHECK_CAP steps.
	if _check != null and spec[1] == "fast" and done >= GODOT_CHECK_CAP:
		return true
	# Reading /proc every step would cost time inside the timed span; one core cannot give
	# a process more CPU time than wall time, so the clock only needs reading once wall time
	# is past the budget.
	if Time.get_ticks_usec() - _clock.wall0 < JOB_BUDGET_S * 1e6:
		return false
	var now := CpuClock.usec()
	if now - _clock.cpu0 < JOB_BUDGET_S * 1e6:
		return false
	if _check != null:
		return done > 0
	return done > WARMUP and now - _cpu0 >= MIN_TIMED_S * 1e6


func _end_job(done: int) -> void:
	var spec: Array = _job["spec"]
	var name: String = spec[0]
	var row: Dictionary = _results[name]
	var checking := _check != null
	var target: int = spec[5] if checking else spec[6]
	if checking:
		row["godot_tunnels"] = _check.tunnels
		row["godot_escapes"] = _check.escapes
		row["godot_steps_checked"] = done
		print(
			(
				"  godot %s: tunnels %d, escapes %d over %d of %d steps"
				% [name, _check.tunnels, _check.escapes, done, target]
			)
		)
	else:
		var timed: int = done - WARMUP
		var balls: int = (_job["scene"]["pos"] as PackedVector2Array).size()
		var cpu: float = maxf((CpuClock.usec() - _cpu0) / 1e6, 1e-6)
		var wall: float = maxf((Time.get_ticks_usec() - _wall0) / 1e6, 1e-6)
		TimingRounds.add_godot(row, balls * timed / wall, balls * timed / cpu)
		row["godot_steps_run"] = done
		row["godot_timed_steps"] = timed
		row["godot_timed_cpu_s"] = cpu
		if done < target:
			row["godot_budget_hit"] = true
		print(
			(
				"  godot %s: %.0f ball-steps/s over %d of %d steps (%.1f s CPU timed)"
				% [name, balls * timed / wall, done, target, cpu]
			)
		)
	var phase: String = "check"
	if not checking:
		phase = "timing %d" % (row["godot_rounds"] as Array).size()
	_clock.end("godot %s %s" % [name, phase], done, target)
	if not _side.free_all():
		row["godot_scene_leaked"] = true
		print("  godot %s: balls went NaN; scene switched off, not freed (freeing hangs)" % name)
	_side = null
	_check = null
	if checking and done < target:
		# The Godot counts cover only the first `done` steps: count ours over the same steps,
		# so the two can be compared.
		_clock.begin()
		var c: Dictionary = OursRunner.run(_job["scene"], done, true)
		row["ours_tunnels_same_steps"] = c["tunnels"]
		row["ours_escapes_same_steps"] = c["escapes"]
		_clock.end("ours %s check, %d steps" % [name, done])
	_want_job = true


## Our timing run of one round, just before Godot's run of the same round.
func _time_ours_round(spec: Array, scene: Dictionary, row: Dictionary) -> void:
	if _floors.has(spec[0]):
		_clock.begin()
		var f: Dictionary = _floors[spec[0]].time_round()
		TimingRounds.add_floor(row, f["floor_steps_per_s"])
		row["floor_pairs_share"] = f["pairs_share"]
		print("  floor %s: %.0f ball-steps/s (CPU)" % [spec[0], f["floor_steps_per_s"]])
		_clock.end("floor %s timing %d" % [spec[0], (row["floor_rounds"] as Array).size()])
	_clock.begin()
	var r: Dictionary = OursRunner.run(scene, spec[6], false)
	TimingRounds.add_ours(row, r["ball_steps_per_s"], r["cpu_ball_steps_per_s"])
	var round_i: int = (row["ours_rounds"] as Array).size()
	print("  ours %s: %.0f ball-steps/s, round %d" % [spec[0], r["ball_steps_per_s"], round_i])
	_clock.end("ours %s timing %d" % [spec[0], round_i])


func _finish() -> void:
	Engine.time_scale = 1.0
	Engine.physics_ticks_per_second = 60
	var out := {
		"scenarios": _results,
		"zoned_vs_brute_S1": _zoned_vs_brute,
		"threads": _threads,
		"thread_scaling": _thread_scaling.get("scaling", 0.0),
		"thread_scaling_runs": _thread_scaling,
		"machine_scaling": _thread_scaling.get("machine_scaling", 0.0),
		"floor_scaling": _thread_scaling.get("floor_scaling", 0.0),
		"two_worlds_scaling": _thread_scaling.get("two_worlds_scaling", 0.0),
		"threads_identical": _threads_identical,
		"thread_hashes": _thread_hashes,
		"scale": _scale,
		"pin_cost_4x": OursRunner.pin_cost(_scale.get("pins", {})),
		"pin_cost_4x_crush": OursRunner.pin_cost(_scale.get("pins_crush", {})),
		"stages_1_thread_us": _stages,
		"stages_all_threads_us": _stages_all,
		"cpus_allowed": PhaseClock.proc_status("Cpus_allowed_list"),
		"godot_job_budget_s": JOB_BUDGET_S,
		"phase_seconds": _clock.phases,
		"seconds": (Time.get_ticks_usec() - _started_usec) / 1e6,
	}
	BenchTable.print_table(out, WARMUP, JOB_BUDGET_S)
	DirAccess.make_dir_recursive_absolute(ProjectSettings.globalize_path("res://build/bench"))
	var f := FileAccess.open(OUT_PATH, FileAccess.WRITE)
	if f == null:
		push_error("bench_physics: cannot write %s" % OUT_PATH)
		quit(1)
		return
	f.store_string(JSON.stringify(out, "  ", false))
	f.close()
	print("wrote %s" % OUT_PATH)
	quit(0)


## Whether scenario `name` runs: all do, unless the command line ends in
## `-- --only=S3,S4` (a quick look at a few scenarios, without the S1 sweeps either).
func _wanted(name: String) -> bool:
	for arg: String in OS.get_cmdline_user_args():
		if arg.begins_with("--only="):
			return name in arg.trim_prefix("--only=").split(",")
	return true
