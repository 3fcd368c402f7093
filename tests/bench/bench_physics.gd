extends SceneTree
## `make bench`: BallWorld against Godot's GodotPhysics2D (PhysicsServer2D) on the same
## scenes, ball-steps per second, tunnels and escapes counted by an independent swept check;
## the zoning-versus-brute-force ratio and the scale sweeps. Prints a table and writes
## build/bench/physics.json. tools/bench.sh pins the process to one CPU (taskset), which is
## how the worker pool gets one thread: its size is only read from project.godot at startup.

const Scenes := preload("res://tests/bench/physics/bench_scenes.gd")
const SweptCheck := preload("res://tests/bench/physics/swept_check.gd")
const GodotSide := preload("res://tests/bench/physics/godot_side.gd")
const Ours := preload("res://tests/bench/physics/ours_runner.gd")
const CpuClock := preload("res://tests/bench/physics/cpu_clock.gd")

const OUT_PATH := "res://build/bench/physics.json"
## Engine physics ticks run this many times faster than the scene's rate, and time_scale
## slows them back down: each tick still integrates 1 / hz, but ticks run back to back.
const SPEEDUP := 100
const WARMUP := Ours.WARMUP

## name, mode, pin pitch, balls, hz, steps
var _specs: Array = [
	["S1", "flow", 24.0, 1000, 240.0, 240],
	["S2", "pile", 24.0, 3000, 240.0, 90],
	["S3", "fast", 12.0, 500, 60.0, 60],
	["S4", "maze", 0.0, 1000, 120.0, 240],
]
var _results := {}
var _scale := {}
var _zoned_vs_brute := 0.0
var _jobs: Array = []
var _job := {}
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
	print(
		(
			"bench_physics: CPUs allowed %s, processors %d"
			% [_cpus_allowed(), OS.get_processor_count()]
		)
	)
	for spec: Array in _specs:
		var scene: Dictionary = Scenes.make(spec[0], spec[1], spec[2], spec[3], spec[4])
		var r: Dictionary = Ours.run(scene, spec[5], false)
		var c: Dictionary = Ours.run(scene, spec[5], true)
		_results[spec[0]] = {
			"ours_steps_per_s": r["ball_steps_per_s"],
			"ours_wall_steps_per_s": r["wall_ball_steps_per_s"],
			"tunnels": c["tunnels"],
			"escapes": c["escapes"],
			"balls": spec[3],
			"pins": (scene["pins"] as PackedVector2Array).size(),
			"walls": (scene["walls"] as PackedVector2Array).size() / 2,
			"hz": spec[4],
			"steps": spec[5],
		}
		print(
			(
				"  ours %s: %.0f ball-steps/s (CPU), tunnels %d, escapes %d"
				% [spec[0], r["ball_steps_per_s"], c["tunnels"], c["escapes"]]
			)
		)
		_jobs.append([spec, scene, false])
		_jobs.append([spec, scene, true])
	_zoned_vs_brute = Ours.zoned_vs_brute(Scenes.make("S1", "flow", 24.0, 1000, 240.0), 12)
	print("  zoned vs brute force (S1): %.1fx" % _zoned_vs_brute)
	_scale = Ours.scale_sweep()
	physics_frame.connect(_on_physics_frame)
	_next_job()


func _next_job() -> void:
	if _side != null:
		_side.free_all()
		_side = null
	if _jobs.is_empty():
		_finish()
		return
	var job: Array = _jobs.pop_front()
	var spec: Array = job[0]
	var scene: Dictionary = job[1]
	_job = {"spec": spec, "scene": scene, "check": job[2]}
	_rng.seed = Ours.RULES_SEED
	var hz: float = spec[4]
	Engine.time_scale = SPEEDUP
	Engine.physics_ticks_per_second = int(hz * SPEEDUP)
	Engine.max_physics_steps_per_frame = 32
	_side = GodotSide.new()
	var maze: bool = spec[1] == "maze"
	var g := PhysicsTuning.pachinko_defaults().gravity
	if maze:
		g = MazeTilt.gravity(Scenes.maze_tilt(0.0), PhysicsTuning.maze_defaults().tilt_gravity)
	_side.build(scene, g, 1.0 / 3.0 if maze else 0.6, spec[1] == "fast")
	_check = SweptCheck.new(scene) if job[2] else null
	_prev = scene["pos"]
	_step_i = 0


## One engine physics tick: the Godot side just stepped (or is about to, the first time).
func _on_physics_frame() -> void:
	if _side == null:
		return
	var spec: Array = _job["spec"]
	var mode: String = spec[1]
	var hz: float = spec[4]
	if _step_i == WARMUP:
		_cpu0 = CpuClock.usec()
		_wall0 = Time.get_ticks_usec()
	if _check != null:
		var pos: PackedVector2Array = _side.positions()
		if _step_i > 0:
			var skip := PackedByteArray()
			skip.resize(pos.size())
			skip.fill(0)
			_check.check(_prev, pos, skip)
		Ours.harness_rules(mode, _step_i, pos, _rng, _side, hz)
		_prev = pos
	elif _step_i > 0 and Ours.rules_due(mode, _step_i):
		var pos := PackedVector2Array() if mode == "maze" else _side.positions()
		Ours.harness_rules(mode, _step_i, pos, _rng, _side, hz)
	_step_i += 1
	if _step_i <= spec[5]:
		return
	var row: Dictionary = _results[spec[0]]
	if _check != null:
		row["godot_tunnels"] = _check.tunnels
		row["godot_escapes"] = _check.escapes
		print("  godot %s: tunnels %d, escapes %d" % [spec[0], _check.tunnels, _check.escapes])
	else:
		var timed: int = spec[5] - WARMUP
		var balls: int = (_job["scene"]["pos"] as PackedVector2Array).size()
		var cpu: float = maxf((CpuClock.usec() - _cpu0) / 1e6, 1e-6)
		var wall: float = maxf((Time.get_ticks_usec() - _wall0) / 1e6, 1e-6)
		row["godot_steps_per_s"] = balls * timed / cpu
		row["godot_wall_steps_per_s"] = balls * timed / wall
		row["ratio"] = row["ours_steps_per_s"] / row["godot_steps_per_s"]
		print("  godot %s: %.0f ball-steps/s (CPU)" % [spec[0], row["godot_steps_per_s"]])
	_next_job()


func _finish() -> void:
	Engine.time_scale = 1.0
	Engine.physics_ticks_per_second = 60
	var out := {
		"scenarios": _results,
		"zoned_vs_brute_S1": _zoned_vs_brute,
		"scale": _scale,
		"cpus_allowed": _cpus_allowed(),
		"seconds": (Time.get_ticks_usec() - _started_usec) / 1e6,
	}
	_print_table(out)
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


func _print_table(out: Dictionary) -> void:
	print("")
	print(
		"scene  balls  pins walls   hz      ours/s     godot/s  ratio  tunnels escapes (godot t/e)"
	)
	for name: String in ["S1", "S2", "S3", "S4"]:
		var r: Dictionary = out["scenarios"][name]
		print(
			(
				"%-5s %6d %5d %5d %4d %11.0f %11.0f %6.2f %8d %7d (%d/%d)"
				% [
					name,
					r["balls"],
					r["pins"],
					r["walls"],
					r["hz"],
					r["ours_steps_per_s"],
					r.get("godot_steps_per_s", 0.0),
					r.get("ratio", 0.0),
					r["tunnels"],
					r["escapes"],
					r.get("godot_tunnels", -1),
					r.get("godot_escapes", -1),
				]
			)
		)
	print("zoned vs brute force, S1: %.1fx" % out["zoned_vs_brute_S1"])
	print("scale: %s" % JSON.stringify(out["scale"]))


func _cpus_allowed() -> String:
	var f := FileAccess.open("/proc/self/status", FileAccess.READ)
	if f == null:
		return "unknown"
	while not f.eof_reached():
		var line := f.get_line()
		if line.begins_with("Cpus_allowed_list:"):
			return line.get_slice(":", 1).strip_edges()
	return "unknown"
