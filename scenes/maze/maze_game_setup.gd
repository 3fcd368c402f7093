class_name MazeGameSetup
extends RefCounted
## Builds the maze screen's parts that come from files: the board the App picked (or the
## classic board when it cannot be read) and the shared pause menu and frame counter scenes.
## Split out of MazeGame, which plays the board.

const PAUSE_MENU := "res://scenes/common/pause_menu.tscn"
const FRAME_COUNTER := "res://scenes/common/frame_counter.tscn"
const FALLBACK_BOARD := "res://levels/maze/classic.board"

## The board loaded (null when not even the fallback could be).
var level: BoardLevel
## Why the board the App picked could not be played ("" when it could).
var problem := ""


## Loads the maze board the App picked; a board that cannot be read or is not a maze is
## reported (`problem`, and an error on the console) and the classic board comes instead.
static func load_level() -> MazeGameSetup:
	var result := MazeGameSetup.new()
	var path := App.current_board_path(BoardLevel.MAZE_NAME)
	var loaded := BoardLoader.load_board(path)
	if loaded.level != null and loaded.level.is_maze():
		result.level = loaded.level
		return result
	result.problem = loaded.error if loaded.level == null else "%s is not a maze board" % path
	push_error("MazeGame: %s" % result.problem)
	if path == FALLBACK_BOARD:
		return result
	result.level = BoardLoader.load_board(FALLBACK_BOARD).level
	return result


## Adds the scene at `path` under `parent` and returns it, or warns and returns null when the
## scene is missing. A frame counter goes bottom left (the side panel's title is top right).
static func add_scene(parent: Node, path: String) -> Node:
	if not ResourceLoader.exists(path):
		push_warning("MazeGame: %s is missing" % path)
		return null
	var packed: PackedScene = load(path)
	var node := packed.instantiate()
	var counter := node as FrameCounter
	if counter != null:
		counter.bottom_left = true
	parent.add_child(node)
	return node
