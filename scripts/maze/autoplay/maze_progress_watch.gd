class_name MazeProgressWatch
extends RefCounted
## Watches one of the pilot's games for progress, so the play analysis can give up a
## hopeless game within seconds instead of playing out its time limit, and say why.
##
## Progress is a ball getting PROGRESS_PX nearer the goal (along the path a ball can roll,
## MazeNav) than it has ever been, or more balls in the goal than ever before. Two verdicts
## end a game early:
## - TRAPPED: a ball has sat for TRAPPED_SECONDS in a part of the board that no path wide
##   enough for a ball joins to the goal (MazeFlood's regions): it can never get out.
## - STUCK: no progress for PATIENCE seconds, though a way may exist (the pilot could not
##   find it, or a ball keeps wedging somewhere).
## The watch only reads positions; the game it watches plays exactly as without it.

enum Verdict { PLAYING, TRAPPED, STUCK }

## A ball must come this much nearer the goal than its best to count as progress, px.
const PROGRESS_PX := 10.0
## Seconds without progress before a game is given up as stuck.
const PATIENCE := 20.0
## Seconds a ball must sit in a region cut off from the goal before it counts as trapped
## (a moment there can be the flood grid's rounding at a wall).
const TRAPPED_SECONDS := 1.0
## Seconds between looks at the balls (each look costs a lattice lookup per ball).
const LOOK_EVERY := 0.25

## The verdict so far.
var verdict: Verdict = Verdict.PLAYING
## The ball (index in the world's ball order, which is the start order) the verdict is
## about; -1 while playing.
var culprit := -1
## Seconds since the last progress.
var idle_seconds := 0.0
## Per ball: the nearest it came to the goal along a ball's path, px (MazeNav.FAR: never
## on a path to it).
var best := PackedFloat32Array()
## Per ball: where it was when it came nearest.
var best_at := PackedVector2Array()

var _nav: MazeNav
var _flood: MazeFlood
var _most_in_goal := 0
var _since_look := 0.0
var _trapped_for := PackedFloat32Array()


## A watch over `ball_count` balls on the board `nav` and `flood` were built for (the
## flood without holes: a hole does not wall a ball in).
func _init(nav: MazeNav, flood: MazeFlood, ball_count: int) -> void:
	_nav = nav
	_flood = flood
	best.resize(ball_count)
	best.fill(INF)
	best_at.resize(ball_count)
	_trapped_for.resize(ball_count)
	_trapped_for.fill(0.0)


## Looks at the balls after `dt` more seconds of play; returns the verdict (PLAYING while
## the game should go on). Once a verdict is in it stays.
func look(positions: PackedVector2Array, balls_in_goal: int, dt: float) -> Verdict:
	if verdict != Verdict.PLAYING:
		return verdict
	idle_seconds += dt
	_since_look += dt
	if _since_look < LOOK_EVERY:
		return verdict
	var passed := _since_look
	_since_look = 0.0
	if balls_in_goal > _most_in_goal:
		_most_in_goal = balls_in_goal
		idle_seconds = 0.0
	for i in mini(positions.size(), best.size()):
		var distance := _nav.distance_at(positions[i])
		if distance < best[i] - PROGRESS_PX:
			idle_seconds = 0.0
			best[i] = distance
			best_at[i] = positions[i]
		_trapped_for[i] = _trapped_for[i] + passed if _cut_off(positions[i]) else 0.0
		if _trapped_for[i] >= TRAPPED_SECONDS:
			verdict = Verdict.TRAPPED
			culprit = i
			return verdict
	if idle_seconds >= PATIENCE:
		verdict = Verdict.STUCK
		culprit = furthest()
	return verdict


## The verdict as a word for reports: "playing", "trapped" or "stuck".
func verdict_name() -> String:
	var names: Array[String] = ["playing", "trapped", "stuck"]
	return names[verdict]


# True when a ball centred at `p` is in a region that does not join the goal.
func _cut_off(p: Vector2) -> bool:
	var label := _flood.region_near(p)
	return label >= 0 and not _flood.region_reaches_goal(label)


## The ball whose best is furthest from the goal: the one that held the game up.
func furthest() -> int:
	var worst := -1
	for i in best.size():
		if worst < 0 or best[i] > best[worst]:
			worst = i
	return worst
