@tool
extends Tree
## The dock's balance table: one line per paying item (BalanceRows) with its payout, catch
## rate ± 95% interval and share of the return, and beside it the share the item had in the
## result shown before (another run, or the same counts at the old payouts), so a designer
## sees what an edit did. A click on a column title sorts by it (again: the other way); a
## click on an item's line selects that item on the board.

## The line of a board item was clicked.
signal item_picked(item: Vector2i)

const BalanceRows := preload("res://addons/board_editor/analysis/balance_rows.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
## Column titles, what each sorts by (BalanceRows.SORT_KEYS, same order) and tooltips.
const TITLES: Array[String] = ["Item", "Pays", "Rate %", "Share %", "Before"]
const TIPS: Array[String] = [
	"Click a line to select the item on the board.",
	"Balls the item pays for a ball it catches.",
	"Per cent of the shots it catches, ± the 95% interval.",
	"Its per cent of all the balls the board gives back.",
	"Its share in the result shown before this one (its payout then, if another).",
]
## Narrowest each column gets, px (the dock is narrow: the item's name takes what is left).
const MIN_WIDTHS: Array[int] = [86, 40, 72, 52, 56]
## Height of one line and of the title row, px (the table grows with all its lines: it
## scrolls with the dock's body, never inside it).
const LINE_PX := 24

var _rows: Array[BalanceRows.Row] = []
var _before: Dictionary[String, BalanceRows.Row] = {}
var _sort_key := "share"
var _ascending := false


func _init() -> void:
	name = "BalanceTable"
	columns = TITLES.size()
	column_titles_visible = true
	hide_root = true
	select_mode = Tree.SELECT_ROW
	scroll_vertical_enabled = false  # every line shows: the dock's body scrolls
	scroll_horizontal_enabled = false  # the item column clips; the rest fits DOCK_WIDTH
	for c in TITLES.size():
		set_column_title(c, TITLES[c])
		set_column_title_tooltip_text(c, TIPS[c])
		set_column_expand(c, c == 0)
		set_column_clip_content(c, c == 0)
		set_column_custom_minimum_width(c, MIN_WIDTHS[c])
	column_title_clicked.connect(_on_title_clicked)
	item_selected.connect(_on_item_selected)
	show_rows([] as Array[BalanceRows.Row], [] as Array[BalanceRows.Row])


## Shows `rows` (BalanceRows.rows) with the shares of `before` beside them (empty: none).
func show_rows(rows: Array[BalanceRows.Row], before: Array[BalanceRows.Row]) -> void:
	_rows = rows
	_before = BalanceRows.by_name(before)
	visible = not rows.is_empty()
	_fill()


## Sorts the lines by column `column` (0 is Item); the same column again turns the order
## round. Names start in board order, numbers with the largest.
func sort_by(column: int) -> void:
	var key: String = BalanceRows.SORT_KEYS[column]
	_ascending = not _ascending if key == _sort_key else key == "name"
	_sort_key = key
	_fill()


## The names on the lines, top to bottom (tests).
func line_names() -> PackedStringArray:
	var names := PackedStringArray()
	var root := get_root()
	if root == null:
		return names
	for line in root.get_children():
		names.append(line.get_text(0))
	return names


## The text of column `column` on the line named `row_name` ("" when there is none).
func cell(row_name: String, column: int) -> String:
	var root := get_root()
	if root == null:
		return ""
	for line in root.get_children():
		if line.get_text(0) == row_name:
			return line.get_text(column)
	return ""


func _fill() -> void:
	clear()
	var root := create_item()
	for row in BalanceRows.sorted(_rows, _sort_key, _ascending, _before):
		var line := create_item(root)
		line.set_text(0, row.name)
		line.set_text(1, str(row.payout))
		line.set_text(2, "%.1f ±%.1f" % [row.rate * 100.0, row.ci95 * 100.0])
		line.set_text(3, "%.1f" % (row.share * 100.0))
		line.set_text(4, _before_text(row))
		line.set_tooltip_text(4, _before_tip(row))
		line.set_metadata(0, row.item)
		for c in range(1, TITLES.size()):
			line.set_text_alignment(c, HORIZONTAL_ALIGNMENT_RIGHT)
	var lines := _rows.size() + 1
	custom_minimum_size = Vector2(0, lines * LINE_PX + 8)


func _before_text(row: BalanceRows.Row) -> String:
	if not _before.has(row.name):
		return "" if _before.is_empty() else "new"
	var old := _before[row.name]
	var text := "%.1f" % (old.share * 100.0)
	if old.payout != row.payout:
		text += " (%d)" % old.payout
	return text


func _before_tip(row: BalanceRows.Row) -> String:
	if not _before.has(row.name):
		return ""
	var old := _before[row.name]
	return (
		"Before: pays %d, caught %.2f%% ± %.2f of the shots, %.1f%% of the return."
		% [old.payout, old.rate * 100.0, old.ci95 * 100.0, old.share * 100.0]
	)


func _on_title_clicked(column: int, _mouse_button: int) -> void:
	sort_by(column)


func _on_item_selected() -> void:
	var line := get_selected()
	if line == null:
		return
	var item: Vector2i = line.get_metadata(0)
	if item != BoardItems.NONE:
		item_picked.emit(item)
