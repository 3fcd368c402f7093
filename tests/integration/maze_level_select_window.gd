extends RefCounted
## The maze level select opened as a player meets it at a screen size: in a stretched window
## (StretchedWindow), with no boards of the player's own, once it has loaded.

const LevelSelectScene := preload("res://scenes/menu/level_select.tscn")
const StretchedWindow := preload("res://tests/integration/stretched_window.gd")


## The maze level select in a window of `size` under `test`, reading the player's own
## boards from `user_root` (an empty folder); returns it once it has loaded.
static func open(test: GutTest, size: Vector2i, user_root: String) -> LevelSelect:
	App.level_select_kind = BoardLevel.MAZE_NAME
	var no_boards := func(node: Node) -> void: node.set("user_root", user_root)
	var node: Node = await StretchedWindow.open(test, LevelSelectScene, size, 1, no_boards)
	var screen := node as LevelSelect
	await test.wait_until(func() -> bool: return not screen.is_loading(), 20.0)
	await test.wait_process_frames(4)
	return screen
