extends RefCounted
## Side-by-side timing rounds of one bench scenario. The machines the bench runs on are
## shared, and their speed drifts by a third or more within a minute; so each round times
## our layer and then GodotPhysics2D on the same scene right after it, and a scenario's
## figures are the medians over its rounds: the ratio is the median of the rounds' own
## ratios, each from two runs seconds apart. Both sides use every core, so the rates that
## count are wall-clock ball-steps per second; CPU-time rates are kept beside them (a side
## that uses two cores well spends about as much CPU time as one that uses one). Where the
## scenario has a GDScript floor (FloorKernel, one thread), each round times it just
## before ours, and its ratios are kept the same way.


## Records our rates (wall clock, and over CPU time) for the round about to start.
static func add_ours(row: Dictionary, wall_steps_per_s: float, cpu_steps_per_s: float) -> void:
	_rounds(row, "ours_rounds").append(wall_steps_per_s)
	_rounds(row, "ours_cpu_rounds").append(cpu_steps_per_s)
	row["ours_steps_per_s"] = median(_rounds(row, "ours_rounds"))
	row["ours_cpu_steps_per_s"] = median(_rounds(row, "ours_cpu_rounds"))


## Records the GDScript floor's rate (see FloorKernel) for the round about to start.
static func add_floor(row: Dictionary, floor_steps_per_s: float) -> void:
	_rounds(row, "floor_rounds").append(floor_steps_per_s)
	row["floor_steps_per_s"] = median(_rounds(row, "floor_rounds"))


## Records GodotPhysics2D's rate for the round whose ours was recorded last, and updates
## the scenario's medians and ratio.
static func add_godot(row: Dictionary, wall_steps_per_s: float, cpu_steps_per_s: float) -> void:
	var ours: Array = _rounds(row, "ours_rounds")
	var steps_per_s: float = wall_steps_per_s
	_rounds(row, "godot_rounds").append(steps_per_s)
	_rounds(row, "godot_cpu_rounds").append(cpu_steps_per_s)
	_rounds(row, "ratio_rounds").append(ours[ours.size() - 1] / maxf(steps_per_s, 1e-9))
	row["godot_steps_per_s"] = median(_rounds(row, "godot_rounds"))
	row["godot_cpu_steps_per_s"] = median(_rounds(row, "godot_cpu_rounds"))
	row["ratio"] = median(_rounds(row, "ratio_rounds"))
	# Only a scenario with a floor gets floor keys (S3 has none).
	var floors: Array = row.get("floor_rounds", [])
	if not floors.is_empty() and floors.size() == ours.size():
		var floor_now: float = floors[floors.size() - 1]
		_rounds(row, "floor_ratio_rounds").append(floor_now / maxf(steps_per_s, 1e-9))
		_rounds(row, "ours_vs_floor_rounds").append(ours[ours.size() - 1] / floor_now)
		row["floor_vs_godot"] = median(_rounds(row, "floor_ratio_rounds"))
		row["ours_vs_floor"] = median(_rounds(row, "ours_vs_floor_rounds"))


## The middle value (the mean of the two middle ones for an even count); 0 when empty.
static func median(values: Array) -> float:
	if values.is_empty():
		return 0.0
	var sorted: Array = values.duplicate()
	sorted.sort()
	var mid: int = sorted.size() / 2
	if sorted.size() % 2 == 1:
		return sorted[mid]
	return (sorted[mid - 1] + sorted[mid]) * 0.5


static func _rounds(row: Dictionary, key: String) -> Array:
	if not row.has(key):
		row[key] = []
	return row[key]
