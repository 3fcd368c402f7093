@tool
extends RefCounted
## Routes viewport input to the active tool and the keyboard commands. Plain object: the
## plugin passes events and the view transform, tests pass synthetic events.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const EditCommands := preload("res://addons/board_editor/core/edit_commands.gd")
const Shortcuts := preload("res://addons/board_editor/ui/shortcuts.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const BoardTool := preload("res://addons/board_editor/tools/board_tool.gd")
const SelectTool := preload("res://addons/board_editor/tools/select_tool.gd")
const PlaceTool := preload("res://addons/board_editor/tools/place_tool.gd")
const PatternTool := preload("res://addons/board_editor/tools/pattern_tool.gd")
const CurveTool := preload("res://addons/board_editor/tools/curve_tool.gd")
const PocketTool := preload("res://addons/board_editor/tools/pocket_tool.gd")
const BonusTool := preload("res://addons/board_editor/bonus/bonus_tool.gd")
const WallTool := preload("res://addons/board_editor/tools/wall_tool.gd")
const HandlesTool := preload("res://addons/board_editor/tools/handles_tool.gd")
const EraseTool := preload("res://addons/board_editor/tools/erase_tool.gd")

const ARROWS := {
	KEY_LEFT: Vector2.LEFT, KEY_RIGHT: Vector2.RIGHT, KEY_UP: Vector2.UP, KEY_DOWN: Vector2.DOWN
}

## Board pixels around the board where presses still belong to the board tool.
const BOARD_MARGIN := 40.0

## The editor state.
var session: BoardEditSession
## Tool id -> tool object.
var tools := {}
# The mouse button whose press the tool took (-1: none): its drag and release are the tool's.
var _owned_press := -1
# The owned press only gave the viewport its focus back: its release does nothing either.
var _focus_press := false
# The owned press was far off the board with a tool that has nothing to do there.
var _idle_press := false


func _init(on_session: BoardEditSession) -> void:
	session = on_session
	tools = {
		BoardEditSession.Tool.SELECT: SelectTool.new(session),
		BoardEditSession.Tool.PIN: PlaceTool.new(session, BoardItems.Kind.PIN),
		BoardEditSession.Tool.PATTERN: PatternTool.new(session),
		BoardEditSession.Tool.CURVE: CurveTool.new(session),
		BoardEditSession.Tool.POCKET: PocketTool.new(session),
		BoardEditSession.Tool.WALL: WallTool.new(session),
		BoardEditSession.Tool.HOLE: PlaceTool.new(session, BoardItems.Kind.HOLE),
		BoardEditSession.Tool.GOAL: PlaceTool.new(session, BoardItems.Kind.GOAL),
		BoardEditSession.Tool.START: PlaceTool.new(session, BoardItems.Kind.START),
		BoardEditSession.Tool.HANDLES: HandlesTool.new(session),
		BoardEditSession.Tool.ERASE: EraseTool.new(session),
		BoardEditSession.Tool.START_POCKET: BonusTool.new(session, BonusPocketSpec.Role.START),
		BoardEditSession.Tool.ATTACKER: BonusTool.new(session, BonusPocketSpec.Role.ATTACKER),
		BoardEditSession.Tool.TULIP: BonusTool.new(session, BonusPocketSpec.Role.TULIP),
		BoardEditSession.Tool.WINDMILL: PlaceTool.new(session, BoardItems.Kind.WINDMILL),
	}
	var rows := BoardEditSession.row_tools()
	for tool in rows:
		tools[tool] = PlaceTool.new(session, rows[tool].pick)


## The active tool.
func active_tool() -> BoardTool:
	return tools[session.tool]


## Handles one event; `to_board` maps viewport pixels to board pixels. True when used.
## While a board is edited the tool owns the viewport's clicks and keys: every click, drag
## and key is used (or swallowed), so nothing reaches Godot's own 2D tools and a click beside
## the board never deselects the board node. Left to Godot: the wheel and the middle button
## (zoom and pan), Ctrl/Cmd/Alt shortcuts the tool does not use (undo, save, new scene) and
## F1-F12.
## `focused` is false when the viewport did not have the keyboard focus: that first press
## only takes the focus back and performs no action.
func handle(event: InputEvent, to_board: Transform2D, focused := true) -> bool:
	if session.level == null:
		return false
	var tool := active_tool()
	tool.pixel = to_board.get_scale().x
	if event is InputEventMouseButton:
		return _mouse_button(tool, event as InputEventMouseButton, to_board, focused)
	if event is InputEventMouseMotion:
		var moved := event as InputEventMouseMotion
		var used := tool.motion(to_board * moved.position, moved)
		var buttons := moved.button_mask & (MOUSE_BUTTON_MASK_LEFT | MOUSE_BUTTON_MASK_RIGHT)
		return (
			used or _owned_press >= 0 or (buttons != 0 and is_over_board(to_board * moved.position))
		)
	if event is InputEventKey:
		var key := event as InputEventKey
		var used := handle_key(key) if key.pressed else false
		return used or owns_key(key)
	return false


## True for a board point on the board, on any item placed off it, or within BOARD_MARGIN
## of either: a drag that starts there is the tool's (a box round pins above the board must
## not fall through to Godot, which would deselect the board and hide the tool).
func is_over_board(at: Vector2) -> bool:
	return edit_area(session.level).grow(BOARD_MARGIN).has_point(at)


## The board's rectangle grown to hold the point of every item stored as points (a pin, a
## wall's ends, a hole, a ball start), on it or not.
static func edit_area(level: BoardLevel) -> Rect2:
	var area := Rect2(Vector2.ZERO, level.size)
	for kind in ItemKinds.all():
		if kind.shape != ItemKind.Shape.POINT and kind.shape != ItemKind.Shape.SEGMENT:
			continue
		var points: PackedVector2Array = level.get(kind.field)
		for point in points:
			if point.is_finite():
				area = area.expand(point)
	return area


## True for a key the board tool keeps from Godot even when it has no use for it: every key
## without Ctrl, Cmd or Alt, except F1-F12 (help, run) and Tab (focus moves).
static func owns_key(key: InputEventKey) -> bool:
	if key.is_command_or_control_pressed() or key.alt_pressed or key.meta_pressed:
		return false
	var code := key.keycode
	return not (code >= KEY_F1 and code <= KEY_F12) and code != KEY_TAB


## True for a key Godot's 2D view zooms on even when the plugin used it: a digit (1 to
## 100 %, 2 to 200 %, Shift+1 to 50 % ...), on the main keys or the keypad, without Ctrl,
## Cmd or Alt. The plugin takes these before the view sees them.
static func is_view_zoom_key(key: InputEventKey) -> bool:
	if key.is_command_or_control_pressed() or key.alt_pressed or key.meta_pressed:
		return false
	var code := key.keycode
	return (code >= KEY_0 and code <= KEY_9) or (code >= KEY_KP_0 and code <= KEY_KP_9)


## Keyboard: tool keys, snap and mirror toggles, flip (H) and mirror to the other half
## (Shift+M), Escape, Delete, Ctrl+C/V/D, arrow nudges.
func handle_key(key: InputEventKey) -> bool:
	var code := key.keycode
	if key.is_command_or_control_pressed():
		return _command_key(key)
	if code == KEY_DELETE or code == KEY_BACKSPACE:
		EditCommands.delete_selection(session)
		return true  # never let the 2D editor delete the board node itself
	if code == KEY_ESCAPE:
		if not active_tool().cancel():
			session.select([])
		return true
	if ARROWS.has(code) and not key.alt_pressed:
		var scale := 10.0 if key.shift_pressed else 1.0
		var arrow: Vector2 = ARROWS[code]
		EditCommands.nudge(session, arrow * scale)
		return true  # with nothing selected the arrows must not move the board node
	return false if key.echo else _toggle_key(key)


func _mouse_button(
	tool: BoardTool, button: InputEventMouseButton, to_board: Transform2D, focused: bool
) -> bool:
	var index := button.button_index
	if index != MOUSE_BUTTON_LEFT and index != MOUSE_BUTTON_RIGHT:
		return false  # wheel zoom and middle-button pan stay Godot's
	var at := to_board * button.position
	if not button.pressed:
		return _mouse_release(tool, button, at)
	if _owned_press < 0:
		_owned_press = index
		_focus_press = not focused
		# Far off the board only the Select tool acts (a box, or a click that clears the
		# selection); the press is still the tool's, so Godot never deselects the board node
		# and closes the tool.
		_idle_press = not is_over_board(at) and session.tool != BoardEditSession.Tool.SELECT
	if _focus_press or _idle_press:
		return true  # a focus click, or a tool with nothing to do off the board
	if index == MOUSE_BUTTON_LEFT:
		tool.press(at, button)
	else:
		tool.cancel()
	return true


# A release belongs to whoever took its press.
func _mouse_release(tool: BoardTool, button: InputEventMouseButton, at: Vector2) -> bool:
	if button.button_index != _owned_press:
		return false
	_owned_press = -1
	if _focus_press or _idle_press:
		_focus_press = false
		_idle_press = false
	elif button.button_index == MOUSE_BUTTON_LEFT:
		tool.release(at, button)
	return true


# Ctrl+C / Ctrl+V / Ctrl+D are the board's even when there is nothing to copy or paste
# (Godot would copy, paste or duplicate the board node: "Can't paste root node"); anything
# else with Ctrl (undo, save...) is the editor's.
func _command_key(key: InputEventKey) -> bool:
	if key.shift_pressed or key.alt_pressed:
		return false
	match key.keycode:
		KEY_C:
			EditCommands.copy_selection(session)
		KEY_V:
			EditCommands.paste_at(session, active_tool().hover)
		KEY_D:
			EditCommands.duplicate_selection(session)
		_:
			return false
	return true


# Snap, mirror, flip and the tool keys.
func _toggle_key(key: InputEventKey) -> bool:
	if key.shift_pressed and key.keycode == Shortcuts.MIRROR_COPY_KEY:
		EditCommands.mirror_to_other_half(session)
		return true
	if key.keycode == Shortcuts.FLIP_KEY and not key.shift_pressed:
		EditCommands.flip_selection(session)
		return true
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
