extends RefCounted
## Runs a bench scene on BallWorld (timing only world.step()), the harness rules both
## engines share (respawn, relaunch, tilt), the zoning-versus-brute-force ratio and the
## scale sweeps.

const BenchScenes := preload("res://tests/bench/physics/bench_scenes.gd")
const SweptCheck := preload("res://tests/bench/physics/swept_check.gd")
const BladeCheck := preload("res://tests/bench/physics/blade_check.gd")

const CpuClock := preload("res://tests/bench/physics/cpu_clock.gd")
const MachineScaling := preload("res://tests/bench/physics/machine_scaling.gd")
const TimingRounds := preload("res://tests/bench/physics/timing_rounds.gd")

## Steps excluded from timing at the start of a run.
const WARMUP := 5
## Respawns and relaunches happen every this many steps.
const RULES_EVERY := 8
const RULES_SEED := 99
## Ball radius of the pin-density sweep: 7 px balls pass the 9 px gaps of a 12 px lattice.
const PIN_SWEEP_BALL_R := 3.5


## BallWorld seen through the same small interface as the Godot side.
class OursSide:
	extends RefCounted
	var world: BallWorld
	var ids: PackedInt32Array

	func _init(w: BallWorld) -> void:
		world = w
		ids = w.get_ids()

	func velocity(i: int) -> Vector2:
		return world.get_ball_velocity(ids[i])

	func teleport(i: int, p: Vector2, v: Vector2) -> void:
		world.set_ball_position(ids[i], p)
		world.set_ball_velocity(ids[i], v)

	func tilt(deg: Vector2) -> void:
		MazeTilt.apply(world, deg)


## The scene as a BallWorld with the seed tuning for its mode.
static func build_world(scene: Dictionary, zoning := true) -> BallWorld:
	var maze: bool = scene["mode"] == "maze"
	var t := TuningPresets.maze() if maze else TuningPresets.pachinko()
	t.fixed_hz = scene["hz"]
	if scene["mode"] == "fast":
		t.max_speed = 4000.0
	var w := BallWorld.new(t)
	w.use_zoning = zoning
	if scene["ring"]:
		w.shapes.set_ring(Vector2.ZERO, BenchScenes.RING_R)
	for p: Vector2 in scene["pins"]:
		w.shapes.add_pin(p, scene["pin_r"], -1, false, t.min_horizontal_speed)
	var walls: PackedVector2Array = scene["walls"]
	for k: int in walls.size() / 2:
		w.shapes.add_wall(walls[2 * k], walls[2 * k + 1], scene["wall_r"])
	for wheel: Array in scene.get("windmills", []):
		w.shapes.add_windmill(
			wheel[0],
			wheel[1],
			wheel[2],
			wheel[3],
			wheel[4],
			wheel[5],
			wheel[6],
			t.min_horizontal_speed
		)
	var pos: PackedVector2Array = scene["pos"]
	var vel: PackedVector2Array = scene["vel"]
	for i: int in pos.size():
		w.spawn_ball(pos[i], vel[i], scene["ball_r"])
	if maze:
		MazeTilt.apply(w, BenchScenes.maze_tilt(0.0))
	w.build_grid()
	return w


## Runs `steps` steps on `threads` threads (0: every core). Timing runs (check false)
## report ball_steps_per_s over wall-clock time past the warm-up (the world may use
## several cores) and cpu_ball_steps_per_s over process CPU time; check runs replay the
## same steps (the world is deterministic) with the swept check after every step and
## report tunnels and escapes (tunnels through pins and walls plus, on a scene with
## windmills, through blades, also apart as "blade_tunnels"). Both report the final
## state_hash.
static func run(
	scene: Dictionary, steps: int, check: bool, zoning := true, threads := 0
) -> Dictionary:
	var w := build_world(scene, zoning)
	if threads > 0:
		w.threads = threads
	var side := OursSide.new(w)
	var checker: SweptCheck = SweptCheck.new(scene) if check else null
	var blades: BladeCheck = BladeCheck.new(scene) if check else null
	var angles := PackedFloat64Array()
	var spins := PackedFloat64Array()
	angles.resize(w.shapes.windmill_count())
	spins.resize(w.shapes.windmill_count())
	# The check follows the path through the substeps; the timed run records nothing.
	w.set_path_recording(check)
	var rng := RandomNumberGenerator.new()
	rng.seed = RULES_SEED
	var dt: float = 1.0 / float(scene["hz"])
	var mode: String = scene["mode"]
	var before := w.get_positions()
	var balls: int = w.ball_count()
	var cpu0 := 0
	var wall0 := 0
	for s: int in steps:
		if s == WARMUP:
			cpu0 = CpuClock.usec()
			wall0 = Time.get_ticks_usec()
		if blades != null:
			for m: int in w.shapes.windmill_count():
				angles[m] = w.shapes.get_windmill_angle(m)
				spins[m] = w.shapes.get_windmill_speed(m)
		w.step(dt)
		if checker != null:
			var after := w.get_positions()
			var skip := PackedByteArray()
			skip.resize(after.size())
			skip.fill(0)
			var paths: Dictionary = w.take_step_paths()
			checker.check_paths(before, after, skip, paths["slots"], paths["points"])
			if w.shapes.windmill_count() > 0:
				blades.check_step(before, after, paths["slots"], paths["points"], angles, spins, dt)
			harness_rules(mode, s + 1, after, rng, side, scene["hz"])
			before = after
		elif rules_due(mode, s + 1):
			harness_rules(mode, s + 1, w.get_positions(), rng, side, scene["hz"])
	var timed: int = maxi(steps - WARMUP, 1)
	var cpu: float = maxf((CpuClock.usec() - cpu0) / 1e6, 1e-6)
	var wall: float = maxf((Time.get_ticks_usec() - wall0) / 1e6, 1e-6)
	return {
		"ball_steps_per_s": balls * timed / wall,
		"cpu_ball_steps_per_s": balls * timed / cpu,
		"tunnels": checker.tunnels + blades.tunnels if checker != null else 0,
		"blade_tunnels": blades.tunnels if blades != null else 0,
		"escapes": checker.escapes if checker != null else 0,
		"hash": w.state_hash(),
		"threads": w.threads,
	}


## Whether the harness rules act after step `step_i` (respawns and relaunches every
## RULES_EVERY steps, the maze tilt every step).
static func rules_due(mode: String, step_i: int) -> bool:
	return mode == "maze" or step_i % RULES_EVERY == 0


## The per-step rules of each scene, the same for both engines. Teleported balls get their
## new position written into `pos`, so the next swept check starts from there.
static func harness_rules(
	mode: String,
	step_i: int,
	pos: PackedVector2Array,
	rng: RandomNumberGenerator,
	side: Object,
	hz: float
) -> void:
	if not rules_due(mode, step_i):
		return
	if mode == "flow" or mode == "windmills":
		for i: int in pos.size():
			if pos[i].y > BenchScenes.RESPAWN_Y:
				var p: Vector2 = BenchScenes.respawn_point(rng)
				side.call("teleport", i, p, Vector2.ZERO)
				pos[i] = p
	elif mode == "fast":
		for i: int in pos.size():
			var v: Vector2 = side.call("velocity", i)
			if v.length() < 500.0:
				side.call("teleport", i, pos[i], BenchScenes.fast_velocity(rng))
	elif mode == "maze":
		side.call("tilt", BenchScenes.maze_tilt(step_i / hz))


## S1's wall-clock speed on every core over its speed on one thread, from alternating
## runs in the same process (the medians of `rounds` each): the parallel stages' gain.
## Each round also times what the machine gives a second thread then (MachineScaling):
## "machine_scaling" (a call-free loop), "floor_scaling" (`floor_round`, a round of the
## scene's GDScript floor, FloorKernel.time_round, on two threads at once; skipped when
## not given) and "two_worlds_scaling" (two one-thread worlds of the scene at once, sharing
## nothing: the most threads could give ours, with no stage boundary and no shared data);
## and "scaling_of_machine" = scaling / machine_scaling, "scaling_of_two_worlds" =
## scaling / two_worlds_scaling.
static func thread_scaling(
	scene: Dictionary, steps: int, rounds: int, floor_round := Callable()
) -> Dictionary:
	var one: Array = []
	var all: Array = []
	var machine: Array = []
	var floors: Array = []
	var worlds: Array = []
	var one_world: Callable = func() -> void: run(scene, steps + WARMUP, false, true, 1)
	for _round: int in rounds:
		machine.append(MachineScaling.round_scaling())
		one.append(run(scene, steps + WARMUP, false, true, 1)["ball_steps_per_s"])
		all.append(run(scene, steps + WARMUP, false, true, 0)["ball_steps_per_s"])
		machine.append(MachineScaling.round_scaling())
		worlds.append(MachineScaling.pair_scaling(one_world, one_world))
		if floor_round.is_valid():
			floors.append(MachineScaling.pair_scaling(floor_round, floor_round))
	var one_median: float = TimingRounds.median(one)
	var all_median: float = TimingRounds.median(all)
	var scaling: float = all_median / maxf(one_median, 1e-9)
	var machine_median: float = TimingRounds.median(machine)
	var worlds_median: float = TimingRounds.median(worlds)
	return {
		"one_thread_steps_per_s": one_median,
		"all_threads_steps_per_s": all_median,
		"scaling": scaling,
		"machine_scaling": machine_median,
		"machine_rounds": machine,
		"floor_scaling": TimingRounds.median(floors),
		"floor_scaling_rounds": floors,
		"two_worlds_scaling": worlds_median,
		"two_worlds_rounds": worlds,
		"scaling_of_machine": scaling / maxf(machine_median, 1e-9),
		"scaling_of_two_worlds": scaling / maxf(worlds_median, 1e-9),
	}


## True when 1, 2 and 4 threads leave the same state_hash after `steps` steps of `scene`
## (harness rules included); also the hashes, by thread count.
static func threads_identical(scene: Dictionary, steps: int) -> Dictionary:
	var hashes := {}
	for threads: int in [1, 2, 4]:
		hashes[str(threads)] = run(scene, steps, false, true, threads)["hash"]
	var same: bool = hashes["2"] == hashes["1"] and hashes["4"] == hashes["1"]
	return {"identical": same, "hashes": hashes}


## S1 ball-steps per second with zoning, divided by the same without it.
static func zoned_vs_brute(scene: Dictionary, steps: int) -> float:
	var zoned: Dictionary = run(scene, steps + WARMUP, false, true)
	var brute: Dictionary = run(scene, steps + WARMUP, false, false)
	return zoned["ball_steps_per_s"] / maxf(brute["ball_steps_per_s"], 1e-9)


## S1 with 250 → 8,000 balls and 1,250 → 5,000 pins (pitch 24 → 17 → 12 px).
static func scale_sweep() -> Dictionary:
	var by_balls := {}
	for n: int in [250, 500, 1000, 2000, 4000, 8000]:
		var scene: Dictionary = BenchScenes.make("S1", "flow", 24.0, n, 240.0)
		# About 400,000 ball-steps each: near a second of CPU, so the 10 ms clock and the
		# host's drift stay small against it.
		var steps: int = clampi(400000 / n, 50, 1600)
		var r: Dictionary = run(scene, steps + WARMUP, false)
		by_balls[str(n)] = r["ball_steps_per_s"]
		print("  scale balls %d: %.0f ball-steps/s" % [n, r["ball_steps_per_s"]])
	return {
		"balls": by_balls,
		"pins": pin_sweep(PIN_SWEEP_BALL_R),
		"pins_crush": pin_sweep(BenchScenes.BALL_R)
	}


## S1 with 1,250 → 5,000 pins (pitch 24 → 17 → 12 px) and 1,000 balls of radius `ball_r`:
## pins → ball-steps per second. With PIN_SWEEP_BALL_R the balls flow through every
## lattice, so the rows differ only in the pins; with the scenes' 5 px balls the 12 px
## lattice (9 px gaps) stops every ball, and 1,000 of them crush into a cap that holds
## about 680 ("pins_crush": a pile of ~5,000 touching pairs, not a pin cost).
static func pin_sweep(ball_r: float) -> Dictionary:
	var by_pins := {}
	for pitch: float in [24.0, 17.0, 12.0]:
		var scene: Dictionary = BenchScenes.make("S1", "flow", pitch, 1000, 240.0, ball_r)
		var pins: int = (scene["pins"] as PackedVector2Array).size()
		var r: Dictionary = run(scene, 400 + WARMUP, false)
		by_pins[str(pins)] = r["ball_steps_per_s"]
		print(
			(
				"  scale pins %d (balls r %.1f): %.0f ball-steps/s"
				% [pins, ball_r, r["ball_steps_per_s"]]
			)
		)
	return by_pins


## Where the time goes on `scene`: µs per step of each stage (see BallWorld.stage_times())
## over `steps` steps past the warm-up, harness rules included. One thread (`threads` 1):
## that thread's CPU time; more: wall time (the pool threads' CPU is not the world's).
static func stage_breakdown(scene: Dictionary, steps: int, threads := 1) -> Dictionary:
	var w := build_world(scene)
	w.threads = threads
	w.profile_cpu_time = threads == 1
	var side := OursSide.new(w)
	var rng := RandomNumberGenerator.new()
	rng.seed = RULES_SEED
	for s: int in steps + WARMUP:
		if s == WARMUP:
			w.profile_stages = true
		w.step(1.0 / float(scene["hz"]))
		if rules_due(scene["mode"], s + 1):
			harness_rules(scene["mode"], s + 1, w.get_positions(), rng, side, scene["hz"])
	return w.stage_times()


## Time per step with 4x the pins over the sweep's first row (pins → ball-steps per second).
static func pin_cost(by_pins: Dictionary) -> float:
	var speeds: Array = by_pins.values()
	if speeds.size() < 2:
		return 0.0
	return float(speeds[0]) / maxf(float(speeds[speeds.size() - 1]), 1e-9)
