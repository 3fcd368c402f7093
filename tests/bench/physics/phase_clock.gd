extends RefCounted
## The bench's phase log: CPU and wall seconds of each phase (a check run, a floor timing, a
## Godot timing round, ...), in the order they ran, for the JSON's "phase_seconds". One
## phase at a time: begin() starts it, end() names and records it.

const CpuClock := preload("res://tests/bench/physics/cpu_clock.gd")

## Phase name → {"cpu_s", "wall_s"} (plus "steps" and "of" for a Godot job).
var phases := {}
## When the running phase began, in CPU and wall microseconds.
var cpu0 := 0
var wall0 := 0


## Starts timing a phase.
func begin() -> void:
	cpu0 = CpuClock.usec()
	wall0 = Time.get_ticks_usec()


## Records the phase begun last as `name`; `steps` of `of` when it was a Godot job.
func end(name: String, steps := -1, of := -1) -> void:
	var phase := {
		"cpu_s": (CpuClock.usec() - cpu0) / 1e6,
		"wall_s": (Time.get_ticks_usec() - wall0) / 1e6,
	}
	if steps >= 0:
		phase["steps"] = steps
		phase["of"] = of
	phases[name] = phase


## A field of /proc/self/status ("Cpus_allowed_list", "Threads"), or "unknown".
static func proc_status(key: String) -> String:
	var f := FileAccess.open("/proc/self/status", FileAccess.READ)
	if f == null:
		return "unknown"
	while not f.eof_reached():
		var line := f.get_line()
		if line.begins_with(key + ":"):
			return line.get_slice(":", 1).strip_edges()
	return "unknown"
