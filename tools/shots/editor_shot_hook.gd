@tool
extends Node
## Screenshot hook for tools/editor_shots.sh. When the editor starts with
## BOARD_EDITOR_SHOT="<scene.tscn>;<tool>;<out.png>" it opens the scene, selects its
## BoardNode, shows a tool in use, saves the editor window as a PNG (shot_capture.gd, the
## same capture as the game's shots) and quits.
## Tools: "pattern" (pachinko: a lattice ghost and a selected pocket), "curve" (pachinko: a
## peg curve being drawn, red ghosts where it crowds pins, a pocket in the Selection panel)
## "wall" (maze: a wall dragged in mirror mode, the holes layer hidden, the view jumped to
## the first problem) or "bonus" (pachinko with a bonus layer: the attacker in the Selection
## panel, the pins layer locked, a tulip dropped onto a start pocket and named by id).

const ENV := "BOARD_EDITOR_SHOT"
const ShotCapture := preload("res://tools/shots/shot_capture.gd")
const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const AddItemsAction := preload("res://addons/board_editor/actions/add_items_action.gd")
const Plugin := preload("res://addons/board_editor/plugin.gd")
const BoardInput := preload("res://addons/board_editor/board_input.gd")

var _plugin: Plugin


func _init(plugin: EditorPlugin) -> void:
	_plugin = plugin as Plugin


func _ready() -> void:
	_run.call_deferred()


## Opens `scene_path` in the editor and selects its BoardNode (the root or the first one
## below it) in the 2D screen, so the board tool edits it; null, with the reason pushed as
## an error, when there is no such scene or it holds no BoardNode.
static func open_board(tree: SceneTree, scene_path: String) -> BoardNode:
	if not ResourceLoader.exists(scene_path):
		push_error("Editor shot: no scene %s." % scene_path)
		return null
	EditorInterface.open_scene_from_path(scene_path)
	for i in 20:
		await tree.process_frame
	var root := EditorInterface.get_edited_scene_root()
	var node: Node = root
	if root != null and not root is BoardNode:
		node = root.find_children("*", "BoardNode", true, false).front()
	if not node is BoardNode:
		push_error("Editor shot: %s has no BoardNode." % scene_path)
		return null
	EditorInterface.set_main_screen_editor("2D")
	EditorInterface.get_selection().clear()
	EditorInterface.get_selection().add_node(node)
	EditorInterface.edit_node(node)
	for i in 20:
		await tree.process_frame
	return node as BoardNode


func _run() -> void:
	var parts := OS.get_environment(ENV).split(";")
	if parts.size() != 3:
		push_error("%s must be '<scene>;<tool>;<png>', got '%s'." % [ENV, ";".join(parts)])
		get_tree().quit(1)
		return
	# The editor only redraws on changes; a screenshot needs frames drawn on demand.
	OS.low_processor_usage_mode = false
	# Never hang the caller: give up after two minutes whatever happens.
	get_tree().create_timer(120.0).timeout.connect(get_tree().quit.bind(1))
	await _frames(60)
	var node := await open_board(get_tree(), parts[0])
	if node == null:
		get_tree().quit(1)
		return
	_stage(parts[1])
	frame_board(node as BoardNode)
	await _frames(5)
	if parts[1] == "wall":
		_plugin.focus_issue(0)  # jump-to-problem: centred and zoomed in
	else:
		_plugin.mark_issue(0)
	var window := EditorInterface.get_base_control().get_viewport()
	var error: Error = await ShotCapture.save(window, parts[2])
	# Take the staged edit back so the board file is left as it was.
	var manager := _plugin.get_undo_redo()
	manager.get_history_undo_redo(manager.get_object_history_id(node)).undo()
	get_tree().quit(0 if error == OK else 1)


# Puts the editor in a state that shows the tool at work.
func _stage(tool_name: String) -> void:
	var session := _plugin.get_session()
	var input := _plugin.get_board_input()
	if session == null:
		push_error("Editor shot: the board editor did not take the node.")
		return
	var level := session.level
	if tool_name == "wall":
		session.set_mirror(true)
		session.set_tool(BoardEditSession.Tool.WALL)
		var cell := level.path_width + level.wall_width
		var tool := input.active_tool()
		var press := InputEventMouseButton.new()
		press.button_index = MOUSE_BUTTON_LEFT
		press.pressed = true
		tool.press(Vector2(2, 3) * cell, press)
		tool.motion(Vector2(4.2, 3) * cell, InputEventMouseMotion.new())
		# A mistake for the validator to catch live: walls that shut in the first ball.
		var start := level.ball_starts[0]
		var corner := (start / cell).floor() * cell
		var trap := BoardItems.empty_set()
		trap["walls"] = PackedVector2Array(
			[
				corner + Vector2(cell, 0),
				corner + Vector2(cell, cell),
				corner + Vector2(0, cell),
				corner + Vector2(cell, cell)
			]
		)
		session.commit(AddItemsAction.new(level, trap, "Add wall"))
		session.select(
			[BoardItems.make(BoardItems.Kind.WALL, level.walls.size() / 2 - 1)] as Array[Vector2i]
		)
		session.set_layer("Holes", true, false)
	elif tool_name == "curve":
		_stage_curve(session, input)
	elif tool_name == "bonus":
		_stage_bonus(session)
	else:
		session.set_tool(BoardEditSession.Tool.PATTERN)
		session.pattern["kind"] = "arc"
		session.pattern["count"] = 7
		session.pattern["radius"] = 60.0
		var tool := input.active_tool()
		tool.set("hover", level.ring_center + Vector2(-120, -150))
		# A mistake for the validator to catch live: a pin dropped onto another.
		var extra := BoardItems.empty_set()
		extra["pins"] = PackedVector2Array([level.pins[40] + Vector2(1.5, 0.5)])
		session.commit(AddItemsAction.new(level, extra, "Add pin"))
		if not level.pockets.is_empty():
			session.select([BoardItems.make(BoardItems.Kind.POCKET, 0)] as Array[Vector2i])
	session.settings_changed.emit()


# A bonus board in the Select tool: the attacker selected (its open seconds and catches in
# the panel), the pins locked so a click can only pick bonus pieces and pockets, and a tulip
# dropped onto the first start pocket for the validator to name.
func _stage_bonus(session: BoardEditSession) -> void:
	var level := session.level
	if level.bonus_pockets.is_empty():
		push_error("Editor shot: the bonus shot needs a board with a bonus layer.")
		return
	var mouth := level.bonus_pockets[0].position + Vector2(18, 6)
	var extra := BoardItems.empty_set()
	extra["bonus"] = [BonusPocketSpec.of_role(BonusPocketSpec.Role.TULIP, mouth, 26.0, 26.0, 3)]
	session.commit(AddItemsAction.new(level, extra, "Add tulip"))
	for i in level.bonus_pockets.size():
		if level.bonus_pockets[i].role == BonusPocketSpec.Role.ATTACKER:
			session.select([BoardItems.make(BoardItems.Kind.BONUS, i)] as Array[Vector2i])
			break
	session.set_layer("Pins", false, true)
	session.set_tool(BoardEditSession.Tool.SELECT)


# A peg curve half drawn over the top of the field, a pocket selected for the panel.
func _stage_curve(session: BoardEditSession, input: BoardInput) -> void:
	var level := session.level
	if not level.pockets.is_empty():
		session.select([BoardItems.make(BoardItems.Kind.POCKET, 0)] as Array[Vector2i])
	session.set_tool(BoardEditSession.Tool.CURVE)
	session.curve["count"] = 20
	var tool := input.active_tool()
	tool.set("pixel", 0.5)
	var press := InputEventMouseButton.new()
	press.button_index = MOUSE_BUTTON_LEFT
	press.pressed = true
	var from := level.ring_center + Vector2(-230, -40)
	tool.press(from, press)
	for k in range(1, 25):
		var t := float(k) / 24.0
		var at := from + Vector2(400.0 * t, -150.0 * sin(t * PI))
		tool.motion(at, InputEventMouseMotion.new())


## Zooms the 2D view out until the whole board fits and centres it. The 2D editor offers no
## plugin API for this, so it uses the canvas editor's own zoom widget and `center_at`.
func frame_board(node: BoardNode) -> void:
	var base := EditorInterface.get_base_control()
	var editors := base.find_children("*", "CanvasItemEditor", true, false)
	if editors.is_empty() or node.level == null:
		return
	var editor: Node = editors[0]
	var zooms := editor.find_children("*", "EditorZoomWidget", true, false)
	var view_size := EditorInterface.get_editor_viewport_2d().get_visible_rect().size
	var board := node.level.size + Vector2.ONE * 40.0
	if not zooms.is_empty():
		var zoom: Node = zooms[0]
		for i in 8:
			var now := float(zoom.call("get_zoom"))
			if board.x * now <= view_size.x and board.y * now <= view_size.y:
				break
			zoom.call("set_zoom_by_increments", -1, false)
		for i in 8:
			zoom.call("set_zoom_by_increments", 1, false)
			var now := float(zoom.call("get_zoom"))
			if board.x * now > view_size.x or board.y * now > view_size.y:
				zoom.call("set_zoom_by_increments", -1, false)
				break
	editor.call("center_at", node.global_position + node.level.size * 0.5)


func _frames(count: int) -> void:
	for i in count:
		await get_tree().process_frame
