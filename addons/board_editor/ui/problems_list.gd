@tool
extends VBoxContainer
## The dock's problem list: one row per validator finding with its whole message (wrapped,
## never cut off), an error or warning icon, and a tooltip with the message and where it
## is. Clicking a row asks the plugin to show that problem on the board. The list grows
## with its rows: it scrolls with the dock's body, never inside it.

## A row was clicked.
signal issue_focused(index: int)

var _title: Label
var _rows: VBoxContainer


func _init() -> void:
	_title = Label.new()
	_title.autowrap_mode = TextServer.AUTOWRAP_WORD_SMART
	add_child(_title)
	_rows = VBoxContainer.new()
	_rows.size_flags_horizontal = Control.SIZE_EXPAND_FILL
	add_child(_rows)


## Shows `issues` ("No problems found." for none); the row `focused` stays highlighted.
func show_issues(issues: Array[BoardIssue], focused := -1) -> void:
	for row in _rows.get_children():
		_rows.remove_child(row)
		row.queue_free()
	var errors := 0
	for issue in issues:
		errors += 1 if issue.is_error() else 0
	_title.text = summary(issues.size() - errors, errors)
	var editor_theme := EditorInterface.get_editor_theme() if Engine.is_editor_hint() else null
	for i in issues.size():
		_rows.add_child(_row(issues[i], i, editor_theme))
	select_issue(focused)


## "Problems: 1 error, 3 warnings" or "No problems found."
static func summary(warnings: int, errors: int) -> String:
	if warnings + errors == 0:
		return "No problems found."
	return (
		"Problems: %d error%s, %d warning%s (click one to show it)"
		% [errors, "" if errors == 1 else "s", warnings, "" if warnings == 1 else "s"]
	)


## How many rows the list shows.
func row_count() -> int:
	return _rows.get_child_count()


## The text of row `index` (for tests and the self-check).
func row_text(index: int) -> String:
	return (_rows.get_child(index) as Button).text


## The tooltip of row `index`.
func row_tooltip(index: int) -> String:
	return (_rows.get_child(index) as Button).tooltip_text


## Highlights row `index` (-1: none) and scrolls the dock's body to it.
func select_issue(index: int) -> void:
	for i in _rows.get_child_count():
		(_rows.get_child(i) as Button).set_pressed_no_signal(i == index)
	var scroll := _scroll_around()
	if index >= 0 and index < _rows.get_child_count() and scroll != null:
		scroll.ensure_control_visible.call_deferred(_rows.get_child(index))


# The ScrollContainer the list scrolls in (the dock's body), or null.
func _scroll_around() -> ScrollContainer:
	var node := get_parent()
	while node != null and not node is ScrollContainer:
		node = node.get_parent()
	return node as ScrollContainer


func _row(issue: BoardIssue, index: int, editor_theme: Theme) -> Button:
	var row := Button.new()
	row.text = issue.message
	row.autowrap_mode = TextServer.AUTOWRAP_WORD_SMART
	row.alignment = HORIZONTAL_ALIGNMENT_LEFT
	row.toggle_mode = true
	row.flat = true
	row.focus_mode = Control.FOCUS_NONE
	row.size_flags_horizontal = Control.SIZE_EXPAND_FILL
	row.custom_minimum_size = Vector2(60, 0)
	var label := "Error" if issue.is_error() else "Warning"
	row.tooltip_text = (
		"%s: %s\nAt (%.0f, %.0f) on the board. Click to zoom to it."
		% [label, issue.message, issue.position.x, issue.position.y]
	)
	if editor_theme != null:
		row.icon = editor_theme.get_icon(
			"StatusError" if issue.is_error() else "StatusWarning", "EditorIcons"
		)
	else:
		row.add_theme_color_override(
			"font_color", Color(1.0, 0.45, 0.4) if issue.is_error() else Color(1.0, 0.8, 0.4)
		)
	row.pressed.connect(func() -> void: issue_focused.emit(index))
	return row
