extends RefCounted
## The table `make bench` prints from build/bench/physics.json's content.


## Prints the scenario rows, the GDScript floor lines, the S1 extras and the phase times.
## `warmup`: untimed steps at the start of each timing run; `budget_s`: a Godot job's budget.
static func print_table(out: Dictionary, warmup: int, budget_s: float) -> void:
	_print_scenarios(out, warmup, budget_s)
	_print_summary(out)
	_print_phases(out)


# One row per scenario, then what the rows mean and the swept-check notes.
static func _print_scenarios(out: Dictionary, warmup: int, budget_s: float) -> void:
	print("")
	print(
		(
			"scene balls  pins walls   hz     ours/s    godot/s   ratio  steps run  tunnels"
			+ " escapes  godot t/e  checked"
		)
	)
	var notes := PackedStringArray()
	for name: String in out["scenarios"]:
		var r: Dictionary = out["scenarios"][name]
		print(
			(
				"%-5s %5d %5d %5d %4d %10.0f %10.0f %7.2f %5d/%-5d %7d %7d %5d/%-5d %3d/%-3d"
				% [
					name,
					r["balls"],
					r["pins"],
					r["walls"],
					r["hz"],
					r["ours_steps_per_s"],
					r.get("godot_steps_per_s", 0.0),
					r.get("ratio", 0.0),
					r["ours_steps_run"],
					r.get("godot_steps_run", 0),
					r["tunnels"],
					r["escapes"],
					r.get("godot_tunnels", -1),
					r.get("godot_escapes", -1),
					r["steps"],
					r.get("godot_steps_checked", 0),
				]
			)
		)
		if r.has("ours_tunnels_same_steps"):
			(
				notes
				. append(
					(
						"%s: Godot checked %d of %d steps; ours over those steps: tunnels %d, escapes %d"
						% [
							name,
							r["godot_steps_checked"],
							r["steps"],
							r["ours_tunnels_same_steps"],
							r["ours_escapes_same_steps"],
						]
					)
				)
			)
	print("steps run: ours/godot in the timing runs (the first %d untimed)" % warmup)
	print("checked: steps the swept check covered, ours/godot (budget %.0f s)" % budget_s)
	for note: String in notes:
		print(note)


# The GDScript floor, zoning, threads, scaling and the per-stage times.
static func _print_summary(out: Dictionary) -> void:
	for name: String in out["scenarios"]:
		var r: Dictionary = out["scenarios"][name]
		if r.has("floor_vs_godot"):
			print(
				(
					"%s floor: %.0f/s, %.2fx Godot (the most a GDScript grid step reaches); ours %.0f%% of it"
					% [
						name,
						r["floor_steps_per_s"],
						r["floor_vs_godot"],
						100.0 * r["ours_vs_floor"]
					]
				)
			)
	print("zoned vs brute force, S1: %.1fx" % out["zoned_vs_brute_S1"])
	print(
		(
			"threads %d; S1 all threads / one thread: %.2fx; 1, 2, 4 threads identical: %s"
			% [out["threads"], out["thread_scaling"], out["threads_identical"]]
		)
	)
	print(
		(
			(
				"the machine in those rounds, what a second thread gave: a call-free loop %.2fx,"
				% out.get("machine_scaling", 0.0)
			)
			+ (
				" the S1 floor %.2fx, two one-thread S1 worlds %.2fx"
				% [out.get("floor_scaling", 0.0), out.get("two_worlds_scaling", 0.0)]
			)
		)
	)
	print("scale: %s" % JSON.stringify(out["scale"]))
	var cost: String = "4x the pins costs %.2fx the time (balls flowing); %.2fx with 5 px balls"
	print(
		(
			(cost + " (a crush: they can't pass a 12 px lattice)")
			% [out["pin_cost_4x"], out["pin_cost_4x_crush"]]
		)
	)
	var headings := {
		"stages_1_thread_us": "one thread, CPU us per step by stage:",
		"stages_all_threads_us": "every core, wall us per step by stage:",
	}
	for key: String in headings:
		print(headings[key])
		var stages: Dictionary = out.get(key, {})
		for scene: String in stages:
			var parts := PackedStringArray()
			for stage: String in stages[scene]:
				parts.append("%s %.0f" % [stage, stages[scene][stage]])
			print("  %s: %s" % [scene, ", ".join(parts)])


# Seconds per phase and the total.
static func _print_phases(out: Dictionary) -> void:
	print("")
	print("seconds per phase (CPU / wall):")
	var phases: Dictionary = out["phase_seconds"]
	for name: String in phases:
		var p: Dictionary = phases[name]
		var steps := ""
		if p.has("steps"):
			steps = "  %d of %d steps" % [p["steps"], p["of"]]
		print("  %-28s %7.1f / %7.1f%s" % [name, p["cpu_s"], p["wall_s"], steps])
	print("total %.1f s wall" % out["seconds"])
