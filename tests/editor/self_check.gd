@tool
extends Node
## Editor self-check for tools/editor_self_check.sh. When the editor starts with
## BOARD_EDITOR_SELF_CHECK="<scene.tscn>" it opens the scene, selects its BoardNode, adds a
## thing through the plugin's undo path, undoes and redoes it through the scene's history,
## saves the scene, reads the board file back from disk, prints the verdict and quits.
## With BOARD_EDITOR_SELF_CHECK_PLAY=1 it also presses play-test: headless, the request
## file must name the board; with a display the game scene must start (and takes the file).

const ENV := "BOARD_EDITOR_SELF_CHECK"
const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const AddItemsAction := preload("res://addons/board_editor/actions/add_items_action.gd")
const Plugin := preload("res://addons/board_editor/plugin.gd")

var _plugin: Plugin
var _problems := PackedStringArray()


func _init(plugin: EditorPlugin) -> void:
	_plugin = plugin as Plugin


func _ready() -> void:
	_run.call_deferred()


func _run() -> void:
	get_tree().create_timer(120.0).timeout.connect(get_tree().quit.bind(1))
	var scene := OS.get_environment(ENV)
	await _frames(30)
	# On a loaded machine the editor's first file scan can still be running here, and a scene
	# opened then does not become the edited one: wait for the scan, then for the scene.
	await _scan_finished()
	EditorInterface.open_scene_from_path(scene)
	var root := await _edited_root(scene)
	if not root is BoardNode:
		_finish(["%s does not open with a BoardNode at its root." % scene])
		return
	EditorInterface.get_selection().clear()
	EditorInterface.get_selection().add_node(root)
	EditorInterface.edit_node(root)
	await _frames(5)
	var fresh := (root as BoardNode).level == null
	if fresh:
		# A node without a board: the dock's "New maze board" button.
		_plugin.new_board(BoardLevel.Kind.MAZE)
		await _frames(5)
	var session: BoardEditSession = _plugin.get_session()
	if session == null:
		_finish(["the plugin did not take the BoardNode."])
		return
	var level := session.level
	var before := _count(level)
	var data := BoardItems.empty_set()
	var key := "walls" if level.is_maze() else "pins"
	var spot := _spot(level)
	data[key] = PackedVector2Array([spot, spot + Vector2(35, 0)] if level.is_maze() else [spot])
	session.commit(AddItemsAction.new(level, data, "Self-check edit"))
	_expect(_count(level) == before + 1, "the edit did not reach the board")
	var manager := _plugin.get_undo_redo()
	var history_id := manager.get_object_history_id(root)
	_expect(
		history_id != EditorUndoRedoManager.GLOBAL_HISTORY, "the edit is not in the scene's history"
	)
	var history := manager.get_history_undo_redo(history_id)
	_expect(
		history.get_current_action_name() == "Self-check edit",
		"the scene history's last step is not the edit"
	)
	history.undo()
	_expect(_count(level) == before, "undo did not take the edit back")
	history.redo()
	_expect(_count(level) == before + 1, "redo did not apply the edit again")
	_check_drag(session, history)
	EditorInterface.save_scene()
	await _frames(5)
	var written := false
	if level.resource_path.is_empty() or level.resource_path.contains("::"):
		# A board built into the scene: its arrays are written in the scene's text.
		var text := FileAccess.get_file_as_string(root.scene_file_path)
		written = text.contains(var_to_str(level.walls if level.is_maze() else level.pins))
	else:
		var saved := ResourceLoader.load(level.resource_path, "", ResourceLoader.CACHE_MODE_IGNORE)
		written = saved is BoardLevel and _count(saved as BoardLevel) == before + 1
	_expect(written, "saving the scene did not write the board")
	if OS.get_environment("BOARD_EDITOR_SELF_CHECK_PLAY") == "1":
		await _check_play_test(level)
	if not fresh:
		await _check_problems_survive_reselect(root as BoardNode)
		session = _plugin.get_session()
		_check_input_stays_in_the_tool(session)
		await _check_drag_everything(session, history)
		_check_node_outside_the_tree(root as BoardNode)
	if fresh:
		for step in 3:  # the drag, the added wall, then the new board itself
			history.undo()
		_expect((root as BoardNode).level == null, "undo did not take the new board back")
	_finish(_problems)


# The dock's play-test button: the request names the board and the game starts. The game only
# plays boards from levels/, so the scratch board is played from a copy there, removed after.
func _check_play_test(level: BoardLevel) -> void:
	var scratch_path := level.resource_path
	var copy := "res://levels/%s/self_check_play.board" % BoardLevel.kind_name(level.kind)
	level.take_over_path(copy)
	_plugin.play_test()
	await _frames(30)
	var named: String = PlaytestRequest.read(PlaytestRequest.PATH)["board"]
	var said := _plugin.get_dock().status_text()
	_expect(EditorInterface.is_playing_scene() or named == copy, "play-test did not start: " + said)
	var playing := EditorInterface.get_playing_scene()
	print("board editor self-check: play-test scene '%s', request '%s'" % [playing, named])
	EditorInterface.stop_playing_scene()
	# Never leave a request or a board copy behind for the next real game.
	DirAccess.remove_absolute(PlaytestRequest.PATH)
	DirAccess.remove_absolute(copy)
	DirAccess.remove_absolute(copy + ".uid")
	level.take_over_path(scratch_path)


# Where the check adds its wall or pin: a quarter of the way into the board, on a grid point
# of a maze (a wall off the grid's lines would leave gaps narrower than a ball: errors).
static func _spot(level: BoardLevel) -> Vector2:
	var spot := level.size * 0.25
	if level.is_maze():
		spot = spot.snapped(Vector2.ONE * (level.path_width + level.wall_width))
	return spot


# A select-tool drag of the thing just added: previewed live, one step in the scene history.
func _check_drag(session: BoardEditSession, history: UndoRedo) -> void:
	var input := _plugin.get_board_input()
	var item := session.level.pins.size() - 1 if session.level.is_pachinko() else -1
	var from := session.level.pins[item] if item >= 0 else _spot(session.level)
	if session.level.is_maze():
		from += Vector2(17.5, 0)  # the middle of the wall added above
	var start := _position(session.level)
	session.set_tool(BoardEditSession.Tool.SELECT)
	var steps := [[true, from], [null, from + Vector2(20, 10)], [null, from + Vector2(40, 40)]]
	steps.append([false, from + Vector2(40, 40)])
	for step: Array in steps:
		var event: InputEvent
		if step[0] == null:
			event = InputEventMouseMotion.new()
		else:
			var button := InputEventMouseButton.new()
			button.button_index = MOUSE_BUTTON_LEFT
			button.pressed = step[0]
			event = button
		(event as InputEventMouse).position = step[1]
		input.handle(event, Transform2D.IDENTITY)
	var moved := _position(session.level)
	_expect(moved != start, "dragging did not move the item")
	_expect(history.get_current_action_name().begins_with("Move"), "the drag is not one step")
	history.undo()
	_expect(_position(session.level) == start, "undo did not take the whole drag back")
	history.redo()
	_expect(_position(session.level) == moved, "redo did not repeat the drag")


# Select the board, select nothing, select it again: the dock, the markers and the node's
# warnings show the same problems each time (they once came back as "No problems found").
func _check_problems_survive_reselect(root: BoardNode) -> void:
	var session: BoardEditSession = _plugin.get_session()
	if BoardValidator.validate(session.level).is_empty():
		# A pin (or start) on top of another: a warning to keep.
		var data := BoardItems.empty_set()
		var twin := (
			session.level.ball_starts[0] if session.level.is_maze() else session.level.pins[0]
		)
		data["starts" if session.level.is_maze() else "pins"] = PackedVector2Array([twin])
		session.commit(AddItemsAction.new(session.level, data, "Self-check overlap"))
		await _frames(2)
	var before: int = _plugin.get_issues().size()
	_expect(before > 0, "the board shows no problems to keep")
	var warnings := root._get_configuration_warnings().size()
	EditorInterface.get_selection().clear()
	EditorInterface.edit_node(null)
	await _frames(5)
	EditorInterface.get_selection().add_node(root)
	EditorInterface.edit_node(root)
	await _frames(5)
	var after: int = _plugin.get_issues().size()
	print("board editor self-check: %d problems before, %d after selecting again" % [before, after])
	_expect(
		after == before, "selecting the board again lost its problems (%d -> %d)" % [before, after]
	)
	_expect(
		root._get_configuration_warnings().size() == warnings,
		"selecting the board again emptied the node's warnings"
	)


# Keys, right-clicks, arrows with nothing selected and drags on empty board go through the
# plugin exactly as the viewport sends them; each must be the board tool's, not Godot's.
func _check_input_stays_in_the_tool(session: BoardEditSession) -> void:
	session.select([])
	var corner := _screen_point(session.level.size - Vector2(3, 3))
	var events: Array[InputEvent] = []
	for code: Key in [KEY_W, KEY_E, KEY_R, KEY_V, KEY_LEFT]:
		var key := InputEventKey.new()
		key.keycode = code
		key.pressed = true
		events.append(key)
	for button: MouseButton in [MOUSE_BUTTON_RIGHT, MOUSE_BUTTON_LEFT]:
		var press := InputEventMouseButton.new()
		press.button_index = button
		press.pressed = true
		press.position = corner
		var drag := InputEventMouseMotion.new()
		drag.position = corner - Vector2(30, 30)
		drag.button_mask = MOUSE_BUTTON_MASK_LEFT if button == MOUSE_BUTTON_LEFT else 0
		var release := press.duplicate() as InputEventMouseButton
		release.pressed = false
		events.append_array([press, drag, release])
	var position := _plugin.get_board_node().position
	for event in events:
		var used: bool = _plugin._forward_canvas_gui_input(event)
		var drag_only := (
			event is InputEventMouseMotion and (event as InputEventMouseMotion).button_mask == 0
		)
		_expect(used or drag_only, "the board tool let %s through to Godot" % event.as_text())
	_expect(_plugin.get_board_node().position == position, "the board node moved")


# Drags every pin and pocket of the board through the plugin with the overlay drawn each
# step; the shell script fails on any error the editor prints meanwhile.
func _check_drag_everything(session: BoardEditSession, history: UndoRedo) -> void:
	var level := session.level
	var everything: Array[Vector2i] = []
	var kinds := {
		BoardItems.Kind.PIN: level.pins.size(), BoardItems.Kind.POCKET: level.pockets.size()
	}
	if level.is_maze():
		kinds = {
			BoardItems.Kind.WALL: BoardItems.wall_count(level.walls),
			BoardItems.Kind.HOLE: level.holes.size()
		}
	for kind: int in kinds:
		for i in int(kinds[kind]):
			everything.append(BoardItems.make(kind, i))
	session.set_tool(BoardEditSession.Tool.SELECT)
	session.select(everything)
	var grab := BoardItems.position_of(level, everything[0])
	var before := BoardItems.position_of(level, everything[0])
	var steps := 12
	for i in steps + 2:
		var event: InputEvent
		if i == 0 or i == steps + 1:
			var button := InputEventMouseButton.new()
			button.button_index = MOUSE_BUTTON_LEFT
			button.pressed = i == 0
			event = button
		else:
			var motion := InputEventMouseMotion.new()
			motion.button_mask = MOUSE_BUTTON_MASK_LEFT
			event = motion
		var offset := Vector2(2, 1) * float(mini(i, steps))
		(event as InputEventMouse).position = _screen_point(grab + offset)
		_plugin._forward_canvas_gui_input(event)
		await _frames(1)
	print(
		(
			"board editor self-check: dragged %d items, the first from %s to %s"
			% [everything.size(), before, BoardItems.position_of(level, everything[0])]
		)
	)
	_expect(
		BoardItems.position_of(level, everything[0]) != before, "dragging everything moved nothing"
	)
	_expect(
		history.get_current_action_name().begins_with("Move"), "dragging everything is not one step"
	)
	history.undo()
	_expect(
		BoardItems.position_of(level, everything[0]) == before, "undo did not put everything back"
	)
	session.select([])


# Ctrl+N and closing a scene take the edited node out of the tree while the plugin still
# draws and gets input: both must quietly do nothing (no "!is_inside_tree()" errors).
func _check_node_outside_the_tree(root: BoardNode) -> void:
	var loose := BoardNode.new()
	loose.level = root.level
	_plugin._edit(loose)
	var overlay := Control.new()
	_plugin._forward_canvas_draw_over_viewport(overlay)
	var key := InputEventKey.new()
	key.keycode = KEY_P
	key.pressed = true
	_plugin._forward_canvas_gui_input(key)
	_plugin._edit(root)
	overlay.free()
	loose.free()


func _screen_point(board_point: Vector2) -> Vector2:
	var node := _plugin.get_board_node()
	return node.get_viewport_transform() * node.get_global_transform() * board_point


func _position(level: BoardLevel) -> Vector2:
	return (
		level.walls[level.walls.size() - 1]
		if level.is_maze()
		else level.pins[level.pins.size() - 1]
	)


func _count(level: BoardLevel) -> int:
	return level.walls.size() / 2 if level.is_maze() else level.pins.size()


func _expect(ok: bool, problem: String) -> void:
	if not ok:
		_problems.append(problem)


func _finish(problems: PackedStringArray) -> void:
	if problems.is_empty():
		print("board editor self-check: ok")
	for problem in problems:
		print("board editor self-check: FAILED: %s" % problem)
	get_tree().quit(0 if problems.is_empty() else 1)


func _scan_finished() -> void:
	var files := EditorInterface.get_resource_filesystem()
	while files.is_scanning():
		await get_tree().process_frame


## The edited scene's root once `scene` is the edited scene (or whatever is edited after 600
## frames, so a scene that never opens still fails with a message).
func _edited_root(scene: String) -> Node:
	for i in 600:
		await get_tree().process_frame
		var root := EditorInterface.get_edited_scene_root()
		if root != null and root.scene_file_path == scene and i >= 10:
			return root
	return EditorInterface.get_edited_scene_root()


func _frames(count: int) -> void:
	for i in count:
		await get_tree().process_frame
