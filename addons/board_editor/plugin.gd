@tool
extends EditorPlugin
## Board editor: select a BoardNode and the 2D viewport edits its BoardLevel. This file only
## wires the editor to the plain parts: the session (state), BoardInput (tools and keys),
## BoardOverlay (drawing), the toolbar, the dock and the file commands (BoardFileCommands:
## save, save as, new board). Every edit is an action committed to
## the edited scene's undo history; the board file is saved with the scene.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardInput := preload("res://addons/board_editor/board_input.gd")
const BoardOverlay := preload("res://addons/board_editor/ui/board_overlay.gd")
const BoardToolbar := preload("res://addons/board_editor/ui/board_toolbar.gd")
const MazeGeneratorButton := preload("res://addons/board_editor/generator/maze_generator_button.gd")
const BoardDock := preload("res://addons/board_editor/ui/board_dock.gd")
const PlayTest := preload("res://addons/board_editor/ui/play_test.gd")
const NewBoard := preload("res://addons/board_editor/core/new_board.gd")
const BoardFileCommands := preload("res://addons/board_editor/ui/board_file_commands.gd")
const Layers := preload("res://addons/board_editor/core/layers.gd")
const ViewFocus := preload("res://addons/board_editor/ui/view_focus.gd")
const FrameSelection := preload("res://addons/board_editor/ui/frame_selection.gd")
const ToolSettings := preload("res://addons/board_editor/core/tool_settings.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
## The one hook for tooling (screenshots, the editor self-check): ToolingHook.
const ToolingHook := preload("res://addons/board_editor/core/tooling_hook.gd")
## Screens this wide (px) or wider give the Board dock a column of its own (dock_slot_for).
const WIDE_SCREEN := 1600
## The Project > Tools entry that starts a new board.
const NEW_BOARD_MENU := "New board..."

var _node: BoardNode
var _session: BoardEditSession
var _board_input: BoardInput
var _toolbar: BoardToolbar
var _generator: MazeGeneratorButton
var _dock: BoardDock
var _files: BoardFileCommands
var _issues: Array[BoardIssue] = []
var _focused_issue := -1
var _refresh_queued := false
var _visible := false
# The 2D viewport's control (handed to the overlay drawing): the focus goes back there.
var _viewport_control: Control
# A dock field took the keyboard focus: the next viewport press only takes it back.
var _focus_in_dock := false
# The tool settings of the last edited board, for the next one (ToolSettings).
var _kept_settings := {}


func _enter_tree() -> void:
	_toolbar = BoardToolbar.new()
	_toolbar.hide()
	_toolbar.play_test_requested.connect(_play_test)
	_generator = MazeGeneratorButton.new()
	_toolbar.add_child(_generator)
	add_control_to_container(CONTAINER_CANVAS_EDITOR_MENU, _toolbar)
	_dock = BoardDock.new()
	_dock.play_test_requested.connect(_play_test)
	_dock.issue_focused.connect(focus_issue)
	_dock.new_board_requested.connect(_new_board)
	_files = BoardFileCommands.new(EditorInterface.get_base_control(), get_session)
	_files.said.connect(_dock.show_message)
	_files.board_named.connect(_refresh)
	_dock.save_as_requested.connect(_files.open_save_as)
	_dock.new_board_file_requested.connect(open_new_board_dialog)
	_dock.field_focused.connect(func() -> void: _focus_in_dock = true)
	_dock.focus_return_requested.connect(_return_focus)
	add_control_to_dock(dock_slot_for(DisplayServer.screen_get_size().x), _dock)
	FrameSelection.follow_view_menu(_on_view_framed)
	add_tool_menu_item(NEW_BOARD_MENU, open_new_board_dialog)
	_dock.analysis.redraw_needed.connect(update_overlays)
	_dock.analysis.results_changed.connect(_refresh)
	_dock.analysis.item_picked.connect(select_item)
	_dock.maze_analysis.redraw_needed.connect(update_overlays)
	ToolingHook.attach(self)


## Where the Board dock goes on a screen `screen_width` px wide: a full-height column of its
## own beside the Inspector's where there is room, under the Inspector on a smaller screen
## (at 1366 px a fifth column pushed the window off the screen); Godot keeps a moved dock.
static func dock_slot_for(screen_width: int) -> DockSlot:
	return DOCK_SLOT_RIGHT_UR if screen_width >= WIDE_SCREEN else DOCK_SLOT_RIGHT_BL


func _exit_tree() -> void:
	_release()
	remove_tool_menu_item(NEW_BOARD_MENU)
	remove_control_from_container(CONTAINER_CANVAS_EDITOR_MENU, _toolbar)
	remove_control_from_docks(_dock)
	_files.free_dialog()
	_toolbar.queue_free()
	_dock.queue_free()


func _handles(object: Object) -> bool:
	return is_board_node(object)


func _edit(object: Object) -> void:
	_release()
	if object == null or not is_board_node(object):
		return
	_node = object as BoardNode
	var level := _node.level
	if level == null:
		_dock.show_board(null, [], true)
		return
	_session = BoardEditSession.new(level)
	ToolSettings.apply(_session, _kept_settings)
	_session.committer = _commit
	_session.selection_changed.connect(_on_selection_changed)
	_session.settings_changed.connect(_on_settings_changed)
	_session.tool_changed.connect(func(_tool: int) -> void: update_overlays())
	_board_input = BoardInput.new(_session)
	level.changed.connect(_on_level_changed)
	_toolbar.bind(_session)
	_generator.bind(_session)
	_toolbar.visible = _visible
	_refresh()


func _make_visible(visible: bool) -> void:
	_visible = visible
	_toolbar.visible = visible and _session != null
	if not visible and _board_input != null:
		_board_input.active_tool().cancel()


func _forward_canvas_gui_input(event: InputEvent) -> bool:
	if not is_instance_valid(_node):
		return false
	var level_now := _node.level
	if level_now != (_session.level if _session != null else null):
		_edit(_node)  # the board resource was set or swapped in the inspector
	if _session == null:
		return false
	if not _node.is_inside_tree():
		return false  # the scene's tab is closing or switching (Ctrl+N): nothing to edit
	var focused := not _focus_in_dock
	if focused and FrameSelection.is_frame_key(event):
		frame_selection()
		return true
	var used := _board_input.handle(event, _to_screen().affine_inverse(), focused)
	if not focused and event is InputEventMouseButton:
		_return_focus()
	if used or event is InputEventMouseMotion:
		update_overlays()
	return used


# Godot's 2D view zooms on the digit keys (1 = 100 %, 2 = 200 % ...) even when the plugin
# used the key (its shortcuts run after the plugins): while the board's viewport has the
# keys, a digit is taken here, before the GUI, and goes to the board tool like any other.
func _input(event: InputEvent) -> void:
	var key := event as InputEventKey
	if key == null or not _visible or _board_input == null or not is_instance_valid(_node):
		return
	if not BoardInput.is_view_zoom_key(key) or _focus_in_dock:
		return
	if not (is_instance_valid(_viewport_control) and _viewport_control.has_focus()):
		return
	if _node.is_inside_tree():
		_board_input.handle(key, _to_screen().affine_inverse())
	get_viewport().set_input_as_handled()


func _forward_canvas_draw_over_viewport(overlay: Control) -> void:
	_viewport_control = overlay
	if _session == null or not is_instance_valid(_node) or not _node.is_inside_tree():
		return
	_dock.analysis.draw_over(overlay, _to_screen())
	_dock.maze_analysis.draw_over(overlay, _to_screen())
	BoardOverlay.draw(
		overlay, _to_screen(), _session, _board_input.active_tool(), _issues, _focused_issue
	)


func _apply_changes() -> void:
	_files.save_boards()


func _save_external_data() -> void:
	_files.save_boards()


## The session editing the selected board (null when none); used by the screenshot hook.
func get_session() -> BoardEditSession:
	return _session


## The input router (null when no board is edited); used by the screenshot hook.
func get_board_input() -> BoardInput:
	return _board_input


## The board tool's dock; used by the self-check and the screenshot hooks.
func get_dock() -> BoardDock:
	return _dock


## The board node being edited (null when none); used by the self-check.
func get_board_node() -> BoardNode:
	return _node if is_instance_valid(_node) else null


## Gives the selected node a fresh board of `kind` (BoardLevel.Kind), as the dock's New
## board button does: one undo step.
func new_board(kind: int) -> void:
	_new_board(kind)


## Saves the boards and play-tests the edited one, as the dock's Play button does.
func play_test() -> void:
	_play_test()


## Marks problem `index` on the board and in the dock's list without moving the view (the
## screenshot hook's still of a marked problem).
func mark_issue(index: int) -> void:
	_focused_issue = index
	update_overlays()


## The problems found on the edited board (a copy; empty when none is edited).
func get_issues() -> Array[BoardIssue]:
	return _issues.duplicate()


## Marks problem `index` on the board (with its message) and in the dock's list, and
## scrolls and zooms the 2D view to frame it (all of it when it covers several items).
func focus_issue(index: int) -> void:
	_focused_issue = index
	_dock.select_issue(index)
	if index >= 0 and index < _issues.size() and is_instance_valid(_node):
		if _node.is_inside_tree():
			var area := _node.get_global_transform() * _issues[index].extent()
			if is_instance_valid(_viewport_control):
				ViewFocus.show_area(area, _viewport_control)
	update_overlays()


## Frames the selected items in the 2D view (the whole board when none is selected), as
## Godot's Frame Selection does for nodes; with `zoom_in` false it only pans (and zooms out
## when they do not fit), as a balance table line does.
func frame_selection(zoom_in := true) -> void:
	if _session == null or not is_instance_valid(_node) or not _node.is_inside_tree():
		return
	if is_instance_valid(_viewport_control):
		var area := FrameSelection.area(_session.level, _session.selection)
		ViewFocus.show_area(_node.get_global_transform() * area, _viewport_control, zoom_in)
	update_overlays()


# Godot framed its node selection from the View menu: frame the board's selection instead.
func _on_view_framed() -> void:
	if _visible:
		frame_selection()


## Selects `item` on the board and brings it into view at the designer's zoom (a line of the
## balance table: reading down the table must not zoom the board to 200 %).
func select_item(item: Vector2i) -> void:
	if _session == null or not BoardItems.is_valid(_session.level, item):
		return
	_session.select([item] as Array[Vector2i])
	frame_selection(false)


## True for the node this plugin edits.
static func is_board_node(object: Object) -> bool:
	return object is BoardNode


func _commit(action: BoardAction, already_applied: bool) -> void:
	var history := get_undo_redo()
	# The board node as context puts the step in the edited scene's history, so the scene
	# is marked changed and Ctrl+Z in the scene undoes it.
	history.create_action(action.get_name(), UndoRedo.MERGE_DISABLE, _node)
	history.add_do_method(action, "do")
	history.add_undo_method(action, "undo")
	history.commit_action(not already_applied)


func _release() -> void:
	if _session != null:
		_kept_settings = ToolSettings.capture(_session)
		if _board_input != null:
			_board_input.active_tool().cancel()
		if _session.level.changed.is_connected(_on_level_changed):
			_session.level.changed.disconnect(_on_level_changed)
	if is_instance_valid(_node):
		_node.editor_hidden_layers = 0
	_session = null
	_board_input = null
	_node = null
	_issues = []  # a new array: never clear one the board node may share
	_focused_issue = -1
	if _toolbar != null:
		_toolbar.hide()
	if _dock != null:
		_dock.show_board(null, [])
		_dock.show_message("")


func _on_level_changed() -> void:
	if _session != null:
		_files.mark_unsaved(_session.level)
	# Many setters fire per edit: validate and redraw once, after the edit.
	if not _refresh_queued:
		_refresh_queued = true
		_refresh.call_deferred()


func _refresh() -> void:
	_refresh_queued = false
	if _session == null:
		return
	_session.prune_selection()
	# Validated here, every time: a board opened or selected again shows its problems at once.
	_issues = BoardValidator.validate(_session.level)
	_issues.append_array(AnalysisWarnings.cached_issues(_session.level))
	_focused_issue = mini(_focused_issue, _issues.size() - 1)
	_dock.show_board(_session, _issues, false, _focused_issue)
	if is_instance_valid(_node):
		_node.update_configuration_warnings()
		_node.queue_redraw()
	update_overlays()


func _on_selection_changed() -> void:
	_dock.refresh_options()
	update_overlays()


func _on_settings_changed() -> void:
	_toolbar.refresh()
	_dock.refresh_options()
	if is_instance_valid(_node) and _session != null:
		_node.editor_hidden_layers = Layers.painter_mask(_session.hidden_layers)
	update_overlays()


func _play_test() -> void:
	if _session != null:
		_files.save_boards()
		_dock.show_message(PlayTest.run(_session.level))


# Gives the selected node a fresh board, undoably (the node's `level` is scene data).
func _new_board(kind: int) -> void:
	if not is_instance_valid(_node):
		return
	var history := get_undo_redo()
	history.create_action(
		"New %s board" % BoardLevel.kind_name(kind), UndoRedo.MERGE_DISABLE, _node
	)
	history.add_do_property(_node, "level", NewBoard.make(kind))
	history.add_undo_property(_node, "level", _node.level)
	history.add_do_method(self, "_rebind", _node)
	history.add_undo_method(self, "_rebind", _node)
	history.commit_action()


func _rebind(node: BoardNode) -> void:
	if is_instance_valid(node) and EditorInterface.get_selection().get_selected_nodes().has(node):
		_edit(node)


## Opens the "New board" dialog (Project > Tools > New board..., or the dock's button).
func open_new_board_dialog() -> void:
	_files.open_new_board_dialog()


# Gives the keyboard back to the 2D viewport, so the tool keys work again after a dock field.
func _return_focus() -> void:
	_focus_in_dock = false
	if is_instance_valid(_viewport_control) and _viewport_control.is_inside_tree():
		_viewport_control.grab_focus()


func _to_screen() -> Transform2D:
	return _node.get_viewport_transform() * _node.get_global_transform()
