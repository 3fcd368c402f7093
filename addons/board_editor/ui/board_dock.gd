@tool
extends VBoxContainer
## The "Board" dock: which board is being edited, its counts, the play-test button, the
## tool settings and the live list of problems (click one to mark it on the board).

signal play_test_requested
signal issue_focused(index: int)

const Session := preload("res://addons/board_editor/board_edit_session.gd")
const ToolOptions := preload("res://addons/board_editor/ui/tool_options.gd")

var _title: Label
var _counts: Label
var _options: ToolOptions
var _problems_title: Label
var _problems: ItemList
var _play: Button


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


## Shows `session`'s board (null: nothing is being edited) and its problems.
func show_board(session: Session, issues: Array[BoardIssue]) -> void:
	var editing := session != null and session.level != null
	_play.disabled = not editing
	_options.visible = editing
	if not editing:
		_title.text = "Select a BoardNode with a board in a scene to edit it here."
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
			level.walls.size() / 2,
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
	var theme := EditorInterface.get_editor_theme() if Engine.is_editor_hint() else null
	for issue in issues:
		var icon: Texture2D = null
		if theme != null:
			icon = theme.get_icon(
				"StatusError" if issue.is_error() else "StatusWarning", "EditorIcons"
			)
		var index := _problems.add_item(issue.message, icon)
		_problems.set_item_tooltip(
			index, "%s at (%.0f, %.0f)" % [issue.kind, issue.position.x, issue.position.y]
		)
	if selected.size() == 1 and selected[0] < issues.size():
		_problems.select(selected[0])
