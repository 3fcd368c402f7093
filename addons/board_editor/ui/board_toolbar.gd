@tool
extends HBoxContainer
## The board editor's toolbar in the 2D editor's menu bar: one button per tool (those the
## board's kind uses), grid snap with its size, mirror mode and play-test.

signal play_test_requested

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const Shortcuts := preload("res://addons/board_editor/ui/shortcuts.gd")

var _session: BoardEditSession
var _buttons := {}
var _snap: CheckButton
var _step: SpinBox
var _mirror: CheckButton


func _init() -> void:
	name = "BoardEditorToolbar"
	add_child(VSeparator.new())
	var group := ButtonGroup.new()
	for tool: int in Shortcuts.tools():
		var button := Button.new()
		button.text = Shortcuts.name_of(tool)
		button.tooltip_text = Shortcuts.tooltip(tool)
		button.toggle_mode = true
		button.theme_type_variation = &"FlatButton"
		button.button_group = group
		button.pressed.connect(_on_tool_pressed.bind(tool))
		_buttons[tool] = button
		add_child(button)
	add_child(VSeparator.new())
	_snap = CheckButton.new()
	_snap.text = "Snap"
	_snap.tooltip_text = (
		(
			"Snap to the grid (%s). On a maze, walls snap to the maze grid and holes, starts and"
			+ " the goal to cell centres; off, everything goes exactly where you click."
		)
		% OS.get_keycode_string(Shortcuts.SNAP_KEY)
	)
	_snap.toggled.connect(func(on: bool) -> void: _session.set_snap(on))
	add_child(_snap)
	_step = SpinBox.new()
	_step.min_value = 1
	_step.max_value = 100
	_step.step = 1
	_step.suffix = "px"
	_step.tooltip_text = "Grid size in pixels (the maze grid is the board's cell size)."
	_step.value_changed.connect(_on_step_changed)
	add_child(_step)
	_mirror = CheckButton.new()
	_mirror.text = "Mirror"
	_mirror.tooltip_text = (
		"Mirror mode (%s): every edit also lands on the other half, mirrored left-right."
		% OS.get_keycode_string(Shortcuts.MIRROR_KEY)
	)
	_mirror.toggled.connect(func(on: bool) -> void: _session.set_mirror(on))
	add_child(_mirror)
	add_child(VSeparator.new())
	var play := Button.new()
	play.text = "Play-test"
	play.tooltip_text = "Save the board and play it in its game."
	play.pressed.connect(func() -> void: play_test_requested.emit())
	add_child(play)


## Shows the state of `session` and edits it from now on.
func bind(session: BoardEditSession) -> void:
	if _session != null:
		_session.tool_changed.disconnect(_on_session_tool)
		_session.settings_changed.disconnect(refresh)
	_session = session
	_session.tool_changed.connect(_on_session_tool)
	_session.settings_changed.connect(refresh)
	refresh()


## Updates every control from the session.
func refresh() -> void:
	if _session == null:
		return
	var available := _session.available_tools()
	for tool: int in _buttons:
		var button: Button = _buttons[tool]
		button.visible = available.has(tool)
		button.set_pressed_no_signal(tool == _session.tool)
	_snap.set_pressed_no_signal(_session.snap_enabled)
	_step.set_value_no_signal(_session.grid_step)
	_step.editable = not _session.level.is_maze()
	_mirror.set_pressed_no_signal(_session.mirror_enabled)


func _on_tool_pressed(tool: int) -> void:
	if _session != null:
		_session.set_tool(tool)


func _on_session_tool(_tool: int) -> void:
	refresh()


func _on_step_changed(value: float) -> void:
	if _session != null:
		_session.grid_step = value
		_session.settings_changed.emit()
