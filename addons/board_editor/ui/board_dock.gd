@tool
extends VBoxContainer
## The "Board" dock: which board is being edited, its counts, the play-test button, the
## tool settings and the live list of problems (click one to mark it on the board).

signal play_test_requested
signal issue_focused(index: int)
signal new_board_requested(kind: int)
signal save_as_requested

const Session := preload("res://addons/board_editor/board_edit_session.gd")
const Items := preload("res://addons/board_editor/core/board_items.gd")
const ToolOptions := preload("res://addons/board_editor/ui/tool_options.gd")
const AnalysisPanel := preload("res://addons/board_editor/analysis/analysis_panel.gd")

## The play-analysis section (Analyze button, progress, figures).
var analysis: AnalysisPanel

var _title: Label
var _counts: Label
var _options: ToolOptions
var _problems_title: Label
var _problems: ItemList
var _play: Button
var _new_box: HBoxContainer
var _save_as: Button
var _status: Label


func _init() -> void:
	name = "Board"
	custom_minimum_size = Vector2(220, 0)
	_title = Label.new()
	_title.autowrap_mode = TextServer.AUTOWRAP_WORD_SMART
	add_child(_title)
	_counts = Label.new()
	add_child(_counts)
	_play = Button.new()
	_play.text = "Play-test this board"
	_play.tooltip_text = "Save the board and run it in its game."
	_play.pressed.connect(func() -> void: play_test_requested.emit())
	add_child(_play)
	_save_as = Button.new()
	_save_as.text = "Save board as a level file"
	_save_as.tooltip_text = "Write the board to levels/<kind>/ so the games and play-test can load it."
	_save_as.pressed.connect(func() -> void: save_as_requested.emit())
	add_child(_save_as)
	_new_box = HBoxContainer.new()
	for kind: int in [BoardLevel.Kind.PACHINKO, BoardLevel.Kind.MAZE]:
		var button := Button.new()
		button.text = "New %s board" % BoardLevel.kind_name(kind)
		button.tooltip_text = "Give this node a new, empty %s board." % BoardLevel.kind_name(kind)
		button.pressed.connect(func() -> void: new_board_requested.emit(kind))
		_new_box.add_child(button)
	add_child(_new_box)
	_status = Label.new()
	_status.autowrap_mode = TextServer.AUTOWRAP_WORD_SMART
	_status.add_theme_color_override("font_color", Color(1.0, 0.75, 0.3))
	add_child(_status)
	analysis = AnalysisPanel.new()
	add_child(analysis)
	add_child(HSeparator.new())
	_options = ToolOptions.new()
	add_child(_options)
	add_child(HSeparator.new())
	_problems_title = Label.new()
	add_child(_problems_title)
	_problems = ItemList.new()
	_problems.custom_minimum_size = Vector2(0, 160)
	_problems.size_flags_vertical = Control.SIZE_EXPAND_FILL
	_problems.auto_height = false
	_problems.item_selected.connect(func(index: int) -> void: issue_focused.emit(index))
	add_child(_problems)
	show_board(null, [])
	show_message("")


## Shows a line of feedback under the buttons ("" hides it).
func show_message(text: String) -> void:
	_status.text = text
	_status.visible = not text.is_empty()


## Shows `session`'s board (null: nothing is being edited) and its problems. With
## `node_without_board` the selected BoardNode has no board yet: offer new ones.
func show_board(session: Session, issues: Array[BoardIssue], node_without_board := false) -> void:
	var editing := session != null and session.level != null
	analysis.bind(session.level if editing else null)
	_play.disabled = not editing
	_options.visible = editing
	_new_box.visible = node_without_board
	var path := session.level.resource_path if editing else ""
	_save_as.visible = editing and (path.is_empty() or path.contains("::"))
	if not editing:
		_title.text = (
			"This BoardNode has no board yet: start a new one."
			if node_without_board
			else "Select a BoardNode with a board in a scene to edit it here."
		)
		_counts.text = ""
		_problems_title.text = ""
		_problems.clear()
		return
	var level := session.level
	_title.text = (
		"%s (%s)\n%s"
		% [
			level.display_name if not level.display_name.is_empty() else "Untitled board",
			BoardLevel.kind_name(level.kind),
			(
				level.resource_path
				if not level.resource_path.is_empty()
				else "not saved to a file yet"
			),
		]
	)
	_counts.text = (
		"Pins: %d   Pockets: %d\nWalls: %d   Holes: %d   Starts: %d"
		% [
			level.pins.size(),
			level.pockets.size(),
			Items.wall_count(level.walls),
			level.holes.size(),
			level.ball_starts.size()
		]
	)
	_options.bind(session)
	_show_issues(issues)


## Updates the tool settings (after a selection or settings change).
func refresh_options() -> void:
	_options.refresh()


## Highlights problem `index` in the list (-1: none).
func select_issue(index: int) -> void:
	if index >= 0 and index < _problems.item_count:
		_problems.select(index)
	else:
		_problems.deselect_all()


func _show_issues(issues: Array[BoardIssue]) -> void:
	var errors := 0
	for issue in issues:
		errors += 1 if issue.is_error() else 0
	var selected := _problems.get_selected_items()
	_problems.clear()
	if issues.is_empty():
		_problems_title.text = "No problems found."
		return
	_problems_title.text = (
		"Problems: %d error%s, %d warning%s"
		% [
			errors,
			"" if errors == 1 else "s",
			issues.size() - errors,
			"" if issues.size() - errors == 1 else "s",
		]
	)
	var editor_theme := EditorInterface.get_editor_theme() if Engine.is_editor_hint() else null
	for issue in issues:
		var icon: Texture2D = null
		if editor_theme != null:
			icon = editor_theme.get_icon(
				"StatusError" if issue.is_error() else "StatusWarning", "EditorIcons"
			)
		var index := _problems.add_item(issue.message, icon)
		_problems.set_item_tooltip(
			index, "%s at (%.0f, %.0f)" % [issue.kind, issue.position.x, issue.position.y]
		)
	if selected.size() == 1 and selected[0] < issues.size():
		_problems.select(selected[0])
