@tool
extends RefCounted
## Routes viewport input to the active tool and the keyboard commands. Plain object: the
## plugin passes events and the view transform, tests pass synthetic events.

const Session := preload("res://addons/board_editor/board_edit_session.gd")
const Commands := preload("res://addons/board_editor/core/edit_commands.gd")
const Shortcuts := preload("res://addons/board_editor/ui/shortcuts.gd")
const Items := preload("res://addons/board_editor/core/board_items.gd")
const BoardTool := preload("res://addons/board_editor/tools/board_tool.gd")
const SelectTool := preload("res://addons/board_editor/tools/select_tool.gd")
const PlaceTool := preload("res://addons/board_editor/tools/place_tool.gd")
const PatternTool := preload("res://addons/board_editor/tools/pattern_tool.gd")
const PocketTool := preload("res://addons/board_editor/tools/pocket_tool.gd")
const BonusTool := preload("res://addons/board_editor/bonus/bonus_tool.gd")
const WallTool := preload("res://addons/board_editor/tools/wall_tool.gd")
const HandlesTool := preload("res://addons/board_editor/tools/handles_tool.gd")
const EraseTool := preload("res://addons/board_editor/tools/erase_tool.gd")

const ARROWS := {
	KEY_LEFT: Vector2.LEFT, KEY_RIGHT: Vector2.RIGHT, KEY_UP: Vector2.UP, KEY_DOWN: Vector2.DOWN
}

## The editor state.
var session: Session
## Tool id -> tool object.
var tools := {}


func _init(on_session: Session) -> void:
	session = on_session
	tools = {
		Session.Tool.SELECT: SelectTool.new(session),
		Session.Tool.PIN: PlaceTool.new(session, Items.Kind.PIN),
		Session.Tool.PATTERN: PatternTool.new(session),
		Session.Tool.POCKET: PocketTool.new(session),
		Session.Tool.WALL: WallTool.new(session),
		Session.Tool.HOLE: PlaceTool.new(session, Items.Kind.HOLE),
		Session.Tool.GOAL: PlaceTool.new(session, Items.Kind.GOAL),
		Session.Tool.START: PlaceTool.new(session, Items.Kind.START),
		Session.Tool.HANDLES: HandlesTool.new(session),
		Session.Tool.ERASE: EraseTool.new(session),
		Session.Tool.START_POCKET: BonusTool.new(session, BonusPocketSpec.Role.START),
		Session.Tool.ATTACKER: BonusTool.new(session, BonusPocketSpec.Role.ATTACKER),
		Session.Tool.TULIP: BonusTool.new(session, BonusPocketSpec.Role.TULIP),
	}


## The active tool.
func active_tool() -> BoardTool:
	return tools[session.tool]


## Handles one event; `to_board` maps viewport pixels to board pixels. True when used.
func handle(event: InputEvent, to_board: Transform2D) -> bool:
	if session.level == null:
		return false
	var tool := active_tool()
	tool.pixel = to_board.get_scale().x
	if event is InputEventMouseButton:
		return _mouse_button(tool, event as InputEventMouseButton, to_board)
	if event is InputEventMouseMotion:
		var moved := event as InputEventMouseMotion
		return tool.motion(to_board * moved.position, moved)
	if event is InputEventKey and (event as InputEventKey).pressed:
		return handle_key(event as InputEventKey)
	return false


## Keyboard: tool keys, snap and mirror toggles, Escape, Delete, Ctrl+C/V/D, arrow nudges.
func handle_key(key: InputEventKey) -> bool:
	var code := key.keycode
	if key.is_command_or_control_pressed():
		return _command_key(key)
	if code == KEY_DELETE or code == KEY_BACKSPACE:
		Commands.delete_selection(session)
		return true  # never let the 2D editor delete the board node itself
	if code == KEY_ESCAPE:
		if not active_tool().cancel():
			session.select([])
		return true
	if ARROWS.has(code) and not key.alt_pressed:
		var scale := 10.0 if key.shift_pressed else 1.0
		var arrow: Vector2 = ARROWS[code]
		return Commands.nudge(session, arrow * scale)
	return false if key.echo else _toggle_key(key)


func _mouse_button(tool: BoardTool, button: InputEventMouseButton, to_board: Transform2D) -> bool:
	var at := to_board * button.position
	if button.button_index == MOUSE_BUTTON_LEFT:
		return tool.press(at, button) if button.pressed else tool.release(at, button)
	if button.button_index == MOUSE_BUTTON_RIGHT and button.pressed:
		return tool.cancel()
	return false


# Ctrl+C / Ctrl+V / Ctrl+D; anything else with Ctrl (undo, save...) is the editor's.
func _command_key(key: InputEventKey) -> bool:
	if key.shift_pressed or key.alt_pressed:
		return false
	match key.keycode:
		KEY_C:
			return Commands.copy_selection(session)
		KEY_V:
			return Commands.paste_at(session, active_tool().hover)
		KEY_D:
			return Commands.duplicate_selection(session)
	return false


# Snap, mirror and the tool keys.
func _toggle_key(key: InputEventKey) -> bool:
	if key.keycode == Shortcuts.SNAP_KEY:
		session.set_snap(not session.snap_enabled)
		return true
	if key.keycode == Shortcuts.MIRROR_KEY:
		session.set_mirror(not session.mirror_enabled)
		return true
	var tool := Shortcuts.tool_for(key)
	if tool < 0 or not session.available_tools().has(tool):
		return false
	active_tool().cancel()
	session.set_tool(tool)
	return true
