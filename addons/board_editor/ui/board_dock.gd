@tool
extends VBoxContainer
## The "Board" dock: which board is being edited, its counts, the play-test button, the
## tool settings and the live list of problems (click one to mark it on the board).
##
## It has a column of its own beside the Inspector (the plugin docks it at the right edge),
## so it gets the window's full height. Everything scrolls in one body, never a scroll
## inside a scroll: the problems and the balance table grow with their lines. Its width is
## fixed (DOCK_WIDTH) and nothing in it may ask for more, so it stays as wide as the
## designer left it; its scroll position stays put when the board is shown again (its rows
## are rebuilt within one frame, before the body is laid out again).

signal play_test_requested
signal issue_focused(index: int)
signal new_board_requested(kind: int)
signal save_as_requested
## "New board…": a new board file and its level scene, opened for editing.
signal new_board_file_requested
## A text field in the dock took the keyboard focus.
signal field_focused
## A field was submitted (Enter): the keyboard should go back to the viewport.
signal focus_return_requested

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const ToolOptions := preload("res://addons/board_editor/ui/tool_options.gd")
const PropertyPanel := preload("res://addons/board_editor/ui/property_panel.gd")
const ProblemsList := preload("res://addons/board_editor/ui/problems_list.gd")
const LayersPanel := preload("res://addons/board_editor/ui/layers_panel.gd")
const FasciaPicker := preload("res://addons/board_editor/ui/fascia_picker.gd")
const AnalysisPanel := preload("res://addons/board_editor/analysis/analysis_panel.gd")
const MazeAnalysisPanel := preload("res://addons/board_editor/analysis/maze_analysis_panel.gd")
## The dock's width, px: the balance table's columns fit in it, and nothing asks for more.
const DOCK_WIDTH := 360.0

## The play-analysis section (Analyze button, progress, figures).
var analysis: AnalysisPanel
## The maze boards' play-analysis section (the autoplay pilot's games).
var maze_analysis: MazeAnalysisPanel

var _title: Label
var _counts: Label
var _machine: FasciaPicker
var _options: ToolOptions
var _properties: PropertyPanel
var _layers: LayersPanel
var _problems: ProblemsList
var _play: Button
var _new_box: HBoxContainer
var _save_as: Button
var _status: Label
var _body: ScrollContainer


func _init() -> void:
	name = "Board"
	custom_minimum_size = Vector2(DOCK_WIDTH, 0)
	# One scrolling body for everything (see the class notes).
	_body = ScrollContainer.new()
	_body.size_flags_vertical = Control.SIZE_EXPAND_FILL
	_body.horizontal_scroll_mode = ScrollContainer.SCROLL_MODE_DISABLED
	add_child(_body)
	var content := VBoxContainer.new()
	content.size_flags_horizontal = Control.SIZE_EXPAND_FILL
	_body.add_child(content)
	_title = Label.new()
	_title.autowrap_mode = TextServer.AUTOWRAP_WORD_SMART
	content.add_child(_title)
	_counts = Label.new()
	_counts.autowrap_mode = TextServer.AUTOWRAP_WORD_SMART
	content.add_child(_counts)
	_machine = FasciaPicker.new()
	content.add_child(_machine)
	var buttons := HFlowContainer.new()
	content.add_child(buttons)
	_play = Button.new()
	_play.text = "Play-test"
	_play.tooltip_text = "Save the board and run it in its game."
	_play.pressed.connect(func() -> void: play_test_requested.emit())
	buttons.add_child(_play)
	_save_as = Button.new()
	_save_as.text = "Save board as..."
	_save_as.tooltip_text = (
		"Name the board and write it to levels/<kind>/<name>.board,\n"
		+ "where the games and play-test find it."
	)
	_save_as.pressed.connect(func() -> void: save_as_requested.emit())
	buttons.add_child(_save_as)
	var new_file := Button.new()
	new_file.text = "New board..."
	new_file.tooltip_text = (
		"Start a new pachinko or maze board: writes levels/<kind>/<name>.board\n"
		+ "and its scene in scenes/boards/, and opens it here (also in Project > Tools)."
	)
	new_file.pressed.connect(func() -> void: new_board_file_requested.emit())
	buttons.add_child(new_file)
	_new_box = HBoxContainer.new()
	for kind: int in [BoardLevel.Kind.PACHINKO, BoardLevel.Kind.MAZE]:
		var button := Button.new()
		button.text = "New %s board" % BoardLevel.kind_name(kind)
		button.tooltip_text = "Give this node a new, empty %s board." % BoardLevel.kind_name(kind)
		button.pressed.connect(func() -> void: new_board_requested.emit(kind))
		_new_box.add_child(button)
	content.add_child(_new_box)
	_status = Label.new()
	_status.autowrap_mode = TextServer.AUTOWRAP_WORD_SMART
	_status.add_theme_color_override("font_color", Color(1.0, 0.75, 0.3))
	content.add_child(_status)
	content.add_child(HSeparator.new())
	# Top to bottom in the order a designer reaches for them: what is wrong, what is
	# selected, the tool's settings, how the board plays, then the layers.
	_problems = ProblemsList.new()
	_problems.issue_focused.connect(func(index: int) -> void: issue_focused.emit(index))
	content.add_child(_problems)
	content.add_child(HSeparator.new())
	_properties = PropertyPanel.new()
	content.add_child(_properties)
	content.add_child(HSeparator.new())
	_options = ToolOptions.new()
	content.add_child(_options)
	content.add_child(HSeparator.new())
	analysis = AnalysisPanel.new()
	content.add_child(analysis)
	maze_analysis = MazeAnalysisPanel.new()
	content.add_child(maze_analysis)
	_layers = LayersPanel.new()
	content.add_child(_layers)
	show_board(null, [])
	show_message("")
	_watch_fields(self)


## The scrolling body (tests read and set its scroll position).
func body() -> ScrollContainer:
	return _body


# Every text field (the spin boxes' too) reports when it takes the focus and hands it
# back on Enter, so the tool keys work again without a click that would also edit.
func _watch_fields(node: Node) -> void:
	for child in node.get_children():
		_watch_fields(child)
	var field := (node as SpinBox).get_line_edit() if node is SpinBox else node as LineEdit
	if field == null:
		if node is BaseButton:
			(node as BaseButton).focus_mode = Control.FOCUS_NONE
		return
	field.focus_entered.connect(func() -> void: field_focused.emit())
	field.text_submitted.connect(
		func(_text: String) -> void:
			field.release_focus()
			focus_return_requested.emit()
	)


## The message line's text now (what the last action said, "" when nothing).
func status_text() -> String:
	return _status.text


## Shows a line of feedback under the buttons ("" hides it).
func show_message(text: String) -> void:
	_status.text = text
	_status.visible = not text.is_empty()


## Shows `session`'s board (null: nothing is being edited) and its problems. With
## `node_without_board` the selected BoardNode has no board yet: offer new ones.
func show_board(
	session: BoardEditSession,
	issues: Array[BoardIssue],
	node_without_board := false,
	focused_issue := -1
) -> void:
	var editing := session != null and session.level != null
	analysis.bind(session.level if editing else null)
	maze_analysis.bind(session.level if editing else null)
	_play.disabled = not editing
	_options.visible = editing
	_properties.visible = editing
	_layers.visible = editing
	_layers.bind(session if editing else null)
	_machine.bind(session if editing else null)
	_new_box.visible = node_without_board
	_save_as.visible = editing
	if not editing:
		_title.text = (
			"This BoardNode has no board yet: start a new one."
			if node_without_board
			else "Select a BoardNode with a board in a scene to edit it here."
		)
		_counts.text = ""
		_problems.show_issues([])
		_problems.visible = false
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
	_counts.text = count_text(level)
	_options.bind(session)
	_properties.bind(session)
	_problems.visible = true
	_problems.show_issues(issues, focused_issue)


## Updates the tool settings (after a selection or settings change).
func refresh_options() -> void:
	_options.refresh()
	_properties.refresh()
	_machine.refresh()
	_layers.refresh()


## The selection panel (the self-check types into its fields).
func properties() -> PropertyPanel:
	return _properties


## The "Machine" row (the board's fascia).
func machine() -> FasciaPicker:
	return _machine


## The layers panel.
func layers() -> LayersPanel:
	return _layers


## The problem list.
func problems() -> ProblemsList:
	return _problems


## Highlights problem `index` in the list (-1: none).
func select_issue(index: int) -> void:
	_problems.select_issue(index)


## What the board holds, in its own kind's words: pins, pockets and the bonus layer on a
## pachinko board; walls, holes and ball starts on a maze.
static func count_text(level: BoardLevel) -> String:
	if level.is_maze():
		return (
			"Walls: %d   Holes: %d   Ball starts: %d"
			% [BoardItems.wall_count(level.walls), level.holes.size(), level.ball_starts.size()]
		)
	return (
		"Pins: %d   Pockets: %d\nStart pockets: %d   Attackers: %d   Tulips: %d"
		% [
			level.pin_pocket.count(-1),  # a pocket's rim pins are part of the pocket
			level.pockets.size(),
			ItemIds.count(level, "start_pockets"),
			ItemIds.count(level, "attackers"),
			ItemIds.count(level, "tulips"),
		]
	)
