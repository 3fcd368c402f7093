class_name MazeAnalysis
extends RefCounted
## The maze's play analysis: the autoplay pilot plays `runs` games (seeds seed, seed+1,
## ...) in easy and in hard mode; the report gives the solve rate and times per mode, which
## holes catch balls, and a difficulty figure: the pilot's expected seconds of play per win
## in hard mode (time played over every run / runs won). Runs are independent games on
## worker threads (high-priority group tasks); results are gathered by run index, so the
## figures never depend on the thread count. A hole is named by its stable id ("id") and
## its place in the board's list ("index").

const DEFAULT_RUNS := 20
## Longest one game is played, seconds (a game without progress is given up sooner:
## MazeProgressWatch).
const RUN_SECONDS := 120.0
## The report's maze figures version: 2 added why each game was lost ("losses", "games").
const MAZE_VERSION := 2
## A running game says how far it is every this many frames (about a second of play).
const PROGRESS_FRAMES := 60

var _level: BoardLevel
var _seed := 1
var _runs := 0
var _threads := 1
var _results: Array[Dictionary] = []
var _mutex := Mutex.new()
var _games_done := 0
# Game index -> the share of its time limit a running game has played (updated each
# PROGRESS_FRAMES frames, dropped when it ends): progress() moves before a game finishes.
var _running_share := {}
var _cancelled := false
var _task := -1
var _started_usec := 0
# Free space for a ball (walls only), shared read-only by the games' watches.
var _flood: MazeFlood
# The board's gaps narrower than a ball (MazeGaps issues), to name what trapped a ball.
var _gaps: Array[BoardIssue] = []


## Plays the runs and returns the report (a plain Dictionary, JSON-ready), blocking.
static func run(level: BoardLevel, runs: int, rng_seed: int, threads: int) -> Dictionary:
	if level == null or not level.is_maze():
		return {"ok": false, "error": "the maze analysis needs a maze board"}
	var analysis := MazeAnalysis.create(level, runs, rng_seed)
	analysis.start(threads)
	analysis.wait()
	return analysis.report()


## An analysis of `level` (a maze; the caller keeps it unchanged while it runs) that plays
## `runs` games per mode from seed `rng_seed`; start() runs it without blocking.
static func create(level: BoardLevel, runs: int, rng_seed: int) -> MazeAnalysis:
	var analysis := MazeAnalysis.new()
	analysis._level = level
	analysis._seed = rng_seed
	analysis._runs = maxi(runs, 1)
	analysis._results.resize(analysis._runs * 2)
	analysis._flood = MazeFlood.new(level, false)
	MazeGaps.check(level, analysis._gaps)
	return analysis


## Starts the games on `threads` worker threads (high priority) and returns at once; poll()
## tells when they are done.
func start(threads: int) -> void:
	_threads = maxi(threads, 1)
	_started_usec = Time.get_ticks_usec()
	_task = WorkerThreadPool.add_group_task(
		_play, games(), mini(_threads, games()), true, "Maze analysis"
	)


## True once every game has finished (or stopped after cancel()).
func poll() -> bool:
	if _task < 0:
		return true
	if not WorkerThreadPool.is_group_task_completed(_task):
		return false
	wait()
	return true


## Blocks until every game has finished (or stopped after cancel()).
func wait() -> void:
	if _task >= 0:
		WorkerThreadPool.wait_for_group_task_completion(_task)
		_task = -1


## Stops the games at their next frame; the report then counts only finished games.
func cancel() -> void:
	_cancelled = true


## True after cancel().
func is_cancelled() -> bool:
	return _cancelled


## Games in all: `runs` easy and `runs` hard.
func games() -> int:
	return _runs * 2


## Games finished so far (any thread may be adding to it).
func games_done() -> int:
	_mutex.lock()
	var done := _games_done
	_mutex.unlock()
	return done


## The share of the run done, 0..1: the finished games, plus each running game's share of
## its time limit (a lower bound: most games end well before the limit, and the share then
## jumps to the whole game).
func progress() -> float:
	_mutex.lock()
	var done := float(_games_done)
	for share: float in _running_share.values():
		done += share
	_mutex.unlock()
	return done / maxf(games(), 1)


## The report of the finished games (call once poll() is true).
func report() -> Dictionary:
	var wall := (Time.get_ticks_usec() - _started_usec) / 1e6
	var figures := {
		"version": AnalysisReport.VERSION,
		"game": BoardLevel.MAZE_NAME,
		"board": _level.board_id,
		"runs": _runs,
		"seed": _seed,
		"threads": _threads,
		"wall_s": snappedf(wall, 0.001),
		"maze_version": MAZE_VERSION,
		"easy": _mode_figures(false),
		"hard": _mode_figures(true),
		"games": _game_list(),
		"losses": MazeLosses.group(_level, _game_list(), _flood, _gaps),
	}
	var hard: Dictionary = figures["hard"]
	figures["difficulty"] = hard["seconds_per_win"]
	return figures


# Game i: runs 0..runs-1 are easy, runs..2·runs-1 hard; seed + (i mod runs). A game ends
# won, lost to a hole, given up (a ball trapped, or stuck without progress) or timed out.
func _play(i: int) -> void:
	var hard := i >= _runs
	var rules := MazeRules.new(_level, hard)
	var out := {"hard": hard, "won": false, "seconds": 0.0, "hole": -1, "reason": "no_board"}
	if rules.is_ready():
		var rng := RandomNumberGenerator.new()
		rng.seed = _seed + i % _runs
		var pilot := MazePilot.new(_level, hard, rng, rules.step_seconds())
		var watch := MazeProgressWatch.new(pilot.nav, _flood, _level.ball_starts.size())
		rules.start()
		var limit := ceili(RUN_SECONDS / rules.step_seconds())
		var frames := 0
		while frames < limit and rules.is_playing():
			if _cancelled:
				_mutex.lock()
				_running_share.erase(i)
				_mutex.unlock()
				return  # an unfinished game counts nowhere
			var world := rules.world
			var positions := world.get_positions()
			var verdict := watch.look(positions, rules.balls_in_goal, rules.step_seconds())
			if verdict != MazeProgressWatch.Verdict.PLAYING:
				break  # hopeless: a ball is trapped, or nothing moved nearer for long
			rules.set_tilt(pilot.decide(positions, world.get_velocities()))
			rules.step()
			frames += 1
			if frames % PROGRESS_FRAMES == 0:
				_mutex.lock()
				_running_share[i] = float(frames) / limit
				_mutex.unlock()
		out = _outcome(rules, watch, hard)
	_mutex.lock()
	_running_share.erase(i)
	_results[i] = out
	_games_done += 1
	_mutex.unlock()


# How a game ended: won, "hole", "trapped", "stuck" or "timeout", the ball that held it up
# ("ball": its start's index, -1 for none) and where ("at"), and where every ball ended.
func _outcome(rules: MazeRules, watch: MazeProgressWatch, hard: bool) -> Dictionary:
	var positions := rules.world.get_positions()
	var out := {
		"hard": hard,
		"won": rules.state == MazeRules.State.WON,
		"seconds": snappedf(rules.elapsed, 0.01),
		"hole": rules.lost_hole,
		"reason": "won",
		"ball": -1,
		"at": [],
		"idle_s": snappedf(watch.idle_seconds, 0.01),
		"ends": _points(positions),
	}
	if out["won"]:
		return out
	if rules.lost_hole >= 0:
		out["reason"] = "hole"
		out["at"] = _hole_at(rules.lost_hole)
		return out
	var ball := watch.culprit
	out["reason"] = watch.verdict_name()
	if watch.verdict == MazeProgressWatch.Verdict.PLAYING:
		out["reason"] = "timeout"
		ball = watch.furthest()
	out["ball"] = ball
	if ball >= 0 and ball < positions.size():
		out["at"] = [snappedf(positions[ball].x, 0.1), snappedf(positions[ball].y, 0.1)]
	return out


# Every finished game's outcome, by game index (easy games first).
func _game_list() -> Array[Dictionary]:
	var list: Array[Dictionary] = []
	for r: Dictionary in _results:
		if not r.is_empty():
			list.append(r)
	return list


static func _points(positions: PackedVector2Array) -> Array:
	var list := []
	for p in positions:
		list.append([snappedf(p.x, 0.1), snappedf(p.y, 0.1)])
	return list


func _mode_figures(hard: bool) -> Dictionary:
	var wins := 0
	var played := 0.0
	var win_times := PackedFloat64Array()
	var holes := {}
	var games_played := 0
	for r: Dictionary in _results:
		if r.is_empty() or r["hard"] != hard:
			continue
		games_played += 1
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
		var id := ItemIds.of(_level, "holes", h)
		hole_list.append({"id": id, "index": h, "balls": holes[h], "at": _hole_at(h)})
	hole_list.sort_custom(func(a: Dictionary, b: Dictionary) -> bool: return a["id"] < b["id"])
	var ci := AnalysisStats.wilson(wins, games_played)
	return {
		"games": games_played,
		"wins": wins,
		"solve_rate": snappedf(float(wins) / maxi(games_played, 1), 0.0001),
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
