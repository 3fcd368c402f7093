extends GutTest
## The bonus tools in the editor: a click with the start pocket, attacker or tulip tool adds
## one (mirrored in mirror mode) in role order, a click on one removes it, each click is one
## undo step, and the board saves and reads back with the same bonus lines.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardInput := preload("res://addons/board_editor/board_input.gd")

var session: BoardEditSession
var input: BoardInput


func _open() -> BoardLevel:
	var level: BoardLevel = (
		(load("res://levels/pachinko/windmills.board") as BoardLevel).duplicate_level()
	)
	session = BoardEditSession.new(level)
	input = BoardInput.new(session)
	session.snap_enabled = false
	return level


func _click(at: Vector2) -> void:
	for down in [true, false]:
		var event := InputEventMouseButton.new()
		event.button_index = MOUSE_BUTTON_LEFT
		event.pressed = down
		event.position = at
		input.handle(event, Transform2D.IDENTITY)


func _roles(level: BoardLevel) -> Array[int]:
	var roles: Array[int] = []
	for spec in level.bonus_pockets:
		roles.append(spec.role)
	return roles


func test_the_three_bonus_tools_place_in_role_order_and_undo() -> void:
	var level := _open()
	assert_true(session.available_tools().has(BoardEditSession.Tool.TULIP))
	session.set_tool(BoardEditSession.Tool.TULIP)
	_click(Vector2(300, 250))
	session.set_tool(BoardEditSession.Tool.START_POCKET)
	_click(Vector2(350, 470))
	session.set_tool(BoardEditSession.Tool.ATTACKER)
	_click(Vector2(350, 600))
	assert_eq(_roles(level), [0, 1, 2], "start pocket, attacker, tulip whatever the click order")
	assert_eq(level.bonus_pockets[1].position, Vector2(350, 600))
	session.history.undo()
	assert_eq(_roles(level), [0, 2], "one click, one undo step")
	session.history.redo()
	assert_eq(_roles(level), [0, 1, 2])


func test_mirror_mode_adds_the_twin_and_a_click_removes_one() -> void:
	var level := _open()
	session.mirror_enabled = true
	session.set_tool(BoardEditSession.Tool.TULIP)
	_click(Vector2(250, 300))
	assert_eq(level.bonus_pockets.size(), 2)
	assert_eq(level.bonus_pockets[1].position, Vector2(450, 300), "mirrored across x = 350")
	_click(Vector2(450, 310))
	assert_eq(level.bonus_pockets.size(), 1, "a click inside a cup removes that pocket")
	assert_eq(level.bonus_pockets[0].position, Vector2(250, 300))


func test_a_placed_board_saves_and_reads_back() -> void:
	var level := _open()
	session.set_tool(BoardEditSession.Tool.START_POCKET)
	_click(Vector2(350, 470))
	var text := BoardTextWriter.write(level)
	assert_string_contains(text, '{"start_pocket": {"id": 1, "x": 350, "y": 470')
	var again: BoardLevel = BoardTextReader.read(text)["level"]
	assert_eq(again.bonus_pockets.size(), 1)
	assert_eq(again.bonus_pockets[0].symbols, 3)
	assert_eq(BoardTextWriter.write(again), text)
