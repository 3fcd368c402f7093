class_name GhostRun
extends RefCounted
## The ghost of the best maze run: the saved replay played in its own world, kept in step with
## the live game, so a view can draw where the best run's balls were at the same moment.
##
## The live game calls `sync(live_steps)` every frame with its world's step count (0 while it
## waits at the start) and `restart()` when it resets; the ghost plays whole recorded frames
## up to that step and then stands still at its finish.

## Plays the best run in its own world (its balls: `positions()`, drawn by
## scenes/maze/maze_ghost_3d.gd).
var player: ReplayPlayer


## Plays `replay` (a maze run recorded on `level`: the caller checked the board hash).
func _init(replay: Replay, level: BoardLevel) -> void:
	player = ReplayPlayer.new(replay, level)


## The ghost of the best run saved for `level` in a mode, or null when there is none, it
## cannot be read, the board changed since it was recorded, or the run was recorded under
## another physics version (a warning says which).
static func load_best(level: BoardLevel, hard: bool) -> GhostRun:
	if level == null or not level.is_maze():
		return null
	var path := ReplayStore.best_maze_path(level.board_id, hard)
	if not FileAccess.file_exists(path):
		return null
	var read := ReplayStore.read_file(path)
	if read.has("error"):
		push_warning("No ghost: %s" % read["error"])
		return null
	var replay: Replay = read["replay"]
	if replay.game != Replay.MAZE or replay.hard != hard or replay.board_id != level.board_id:
		push_warning("No ghost: %s is not a %s run on this board" % [path, replay.mode_name()])
		return null
	if not replay.physics_problem().is_empty():
		push_warning("No ghost: %s %s" % [path, replay.physics_problem()])
		return null
	if not replay.recorded_on(level):
		push_warning("No ghost: the board changed since %s was recorded" % path)
		return null
	return GhostRun.new(replay, level)


## Back to the start of the run (the live game was reset).
func restart() -> void:
	player = ReplayPlayer.new(player.replay, player.maze.level)


## Plays the best run up to `live_steps` fixed steps (never past it).
func sync(live_steps: int) -> void:
	player.advance_to(live_steps)


## The ghost's ball centres now, in board pixels.
func positions() -> PackedVector2Array:
	var world := player.world()
	return world.get_positions() if world != null else PackedVector2Array()


## The ghost's ball radius, in board pixels.
func ball_radius() -> float:
	return player.maze.level.ball_radius


## Steps the ghost has played.
func steps() -> int:
	return player.steps()


## True once the ghost reached the end of its run (it stays where it finished).
func is_finished() -> bool:
	return player.is_done()


## The best run's time in seconds, as recorded.
func seconds() -> float:
	return player.replay.seconds
