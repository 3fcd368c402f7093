extends SceneTree
## Where a step's time goes: runs bench scenes on BallWorld with profile_stages on and
## prints the wall time per stage (µs per step) for one thread and for every core.
## tools/godot.sh --headless --path . -s res://tests/bench/physics/stage_profile.gd \
##     -- [--only=S1] [--pitch=12] [--ball_r=3.5] [--steps=300]
## `--pitch` overrides the pin pitch of the pin scenes (S1 at 12 is the 4×-pins case).

const BenchScenes := preload("res://tests/bench/physics/bench_scenes.gd")
const OursRunner := preload("res://tests/bench/physics/ours_runner.gd")

const SPECS: Array = [
	["S1", "flow", 24.0, 1000, 240.0],
	["S2", "pile", 24.0, 3000, 240.0],
	["S4", "maze", 0.0, 1000, 120.0],
]


func _initialize() -> void:
	var args := {}
	for a: String in OS.get_cmdline_user_args():
		var kv: PackedStringArray = a.trim_prefix("--").split("=", true, 1)
		args[kv[0]] = kv[1] if kv.size() > 1 else ""
	var steps: int = int(args.get("steps", "300"))
	for spec: Array in SPECS:
		if args.has("only") and args["only"] != spec[0]:
			continue
		var pitch: float = float(args.get("pitch", str(spec[2])))
		var ball_r: float = float(args.get("ball_r", str(BenchScenes.BALL_R)))
		var scene: Dictionary = BenchScenes.make(spec[0], spec[1], pitch, spec[3], spec[4], ball_r)
		var counts: Array = [1] if args.has("one") else [1, OS.get_processor_count()]
		for threads: int in counts:
			print(
				(
					"%s pitch %s, %d thread(s): %s"
					% [spec[0], pitch, threads, _profile(scene, steps, threads)]
				)
			)
	quit()


static func _profile(scene: Dictionary, steps: int, threads: int) -> String:
	var w: BallWorld = OursRunner.build_world(scene)
	w.threads = threads
	# One thread: its CPU time (the machine is shared); all cores: wall time.
	w.profile_cpu_time = threads == 1
	var side := OursRunner.OursSide.new(w)
	var rng := RandomNumberGenerator.new()
	rng.seed = OursRunner.RULES_SEED
	var dt: float = 1.0 / float(scene["hz"])
	for s: int in steps:
		if s == OursRunner.WARMUP:
			w.profile_stages = true
		w.step(dt)
		if OursRunner.rules_due(scene["mode"], s + 1):
			OursRunner.harness_rules(
				scene["mode"], s + 1, w.get_positions(), rng, side, scene["hz"]
			)
	var t: Dictionary = w.stage_times()
	var parts := PackedStringArray()
	for k: String in t:
		parts.append("%s %.0f" % [k, t[k]])
	var awake := 0
	for id: int in w.get_ids():
		awake += 0 if w.is_ball_asleep(id) else 1
	var tail := "awake at end %d of %d, state hash %d" % [awake, w.ball_count(), w.state_hash()]
	return "%s | %s" % [", ".join(parts), tail]
