class_name MazeAnalysis
extends RefCounted
## The maze's play analysis: the autoplay pilot plays `runs` games (seeds seed, seed+1,
## ...) in easy and in hard mode; the report gives the solve rate and times per mode, which
## holes catch balls, and a difficulty figure: the pilot's expected seconds of play per win
## in hard mode (time played over every run / runs won). Runs are independent games on
## worker threads (high-priority group tasks); results are gathered by run index, so the
## figures never depend on the thread count.

const MazePilot := preload("res://scripts/maze/autoplay/maze_pilot.gd")

const DEFAULT_RUNS := 20
## Longest one game is played, seconds.
const RUN_SECONDS := 120.0

var _level: BoardLevel
var _seed := 1
var _runs := 0
var _results: Array[Dictionary] = []
var _mutex := Mutex.new()


## Plays the runs and returns the report (a plain Dictionary, JSON-ready).
static func run(level: BoardLevel, runs: int, rng_seed: int, threads: int) -> Dictionary:
	if level == null or not level.is_maze():
		return {"ok": false, "error": "the maze analysis needs a maze board"}
	var analysis := MazeAnalysis.new()
	analysis._level = level
	analysis._seed = rng_seed
	analysis._runs = maxi(runs, 1)
	var started := Time.get_ticks_usec()
	analysis._results.resize(analysis._runs * 2)
	var count := analysis._runs * 2
	if threads <= 1:
		for i in count:
			analysis._play(i)
	else:
		var task := WorkerThreadPool.add_group_task(
			analysis._play, count, mini(threads, count), true, "Maze analysis"
		)
		WorkerThreadPool.wait_for_group_task_completion(task)
	var wall := (Time.get_ticks_usec() - started) / 1e6
	var report := {
		"version": AnalysisReport.VERSION,
		"game": "maze",
		"board": level.board_id,
		"runs": analysis._runs,
		"seed": rng_seed,
		"threads": threads,
		"wall_s": snappedf(wall, 0.001),
		"easy": analysis._mode_figures(false),
		"hard": analysis._mode_figures(true),
	}
	var hard: Dictionary = report["hard"]
	report["difficulty"] = hard["seconds_per_win"]
	return report


# Game i: runs 0..runs-1 are easy, runs..2·runs-1 hard; seed + (i mod runs).
func _play(i: int) -> void:
	var hard := i >= _runs
	var rules := MazeRules.new(_level, hard)
	var out := {"hard": hard, "won": false, "seconds": 0.0, "hole": -1}
	if rules.is_ready():
		var rng := RandomNumberGenerator.new()
		rng.seed = _seed + i % _runs
		var pilot := MazePilot.new(_level, hard, rng, rules.step_seconds())
		rules.start()
		var limit := ceili(RUN_SECONDS / rules.step_seconds())
		var frames := 0
		while frames < limit and rules.is_playing():
			var world := rules.world
			rules.set_tilt(pilot.decide(world.get_positions(), world.get_velocities()))
			rules.step()
			frames += 1
		out["won"] = rules.state == MazeRules.State.WON
		out["seconds"] = rules.elapsed
		out["hole"] = rules.lost_hole
	_mutex.lock()
	_results[i] = out
	_mutex.unlock()


func _mode_figures(hard: bool) -> Dictionary:
	var wins := 0
	var played := 0.0
	var win_times := PackedFloat64Array()
	var holes := {}
	for r: Dictionary in _results:
		if r.is_empty() or r["hard"] != hard:
			continue
		played += r["seconds"]
		if r["won"]:
			wins += 1
			var seconds: float = r["seconds"]
			win_times.append(seconds)
		elif r["hole"] >= 0:
			holes[r["hole"]] = holes.get(r["hole"], 0) + 1
	win_times.sort()
	var hole_list: Array[Dictionary] = []
	for h: int in holes.keys():
		hole_list.append({"id": h, "balls": holes[h], "at": _hole_at(h)})
	hole_list.sort_custom(func(a: Dictionary, b: Dictionary) -> bool: return a["id"] < b["id"])
	var ci := AnalysisStats.wilson(wins, _runs)
	return {
		"solve_rate": snappedf(float(wins) / _runs, 0.0001),
		"solve_rate_ci95": snappedf((ci.y - ci.x) * 0.5, 0.0001),
		"median_time_s": snappedf(_median(win_times), 0.01) if wins > 0 else -1.0,
		"mean_time_s": snappedf(_mean(win_times), 0.01) if wins > 0 else -1.0,
		"seconds_per_win": snappedf(played / wins, 0.01) if wins > 0 else -1.0,
		"holes": hole_list,
	}


func _hole_at(h: int) -> Array[float]:
	if h < 0 or h >= _level.holes.size():
		return []
	return [_level.holes[h].x, _level.holes[h].y]


static func _median(sorted: PackedFloat64Array) -> float:
	@warning_ignore("integer_division")  # the middle element (upper middle for an even count)
	return sorted[sorted.size() / 2]


static func _mean(values: PackedFloat64Array) -> float:
	var s := 0.0
	for v in values:
		s += v
	return s / maxf(values.size(), 1)
