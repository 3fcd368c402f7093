@tool
extends RefCounted
## The rows of the dock's balance table, from an analysis report (AnalysisReport, priced
## with the board's payouts: ReportPayouts): one row per paying item (the pockets, then the
## bonus pieces) with its catch rate and 95% interval, its payout and its share of the
## return, and a last row for the shots that rolled back down the rail (each gives its ball
## back). The shares add up to 1 whenever anything came back.

const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const ItemNames := preload("res://addons/board_editor/core/item_names.gd")
## The name of the row for shots that came back down the rail.
const ROLLED_BACK := "Rolled back"
## What a table can be sorted by (Row fields; "before" is the share in the earlier result).
const SORT_KEYS: Array[String] = ["name", "payout", "rate", "share", "before"]


## One line of the table.
class Row:
	extends RefCounted
	## "Pocket 3", "Tulip 2": stable ids, so a row of an older result finds its item's row in
	## a newer one.
	var name := ""
	## The board item (BoardItems.NONE for the rail).
	var item := Vector2i(-1, -1)
	## Where it stands in board order (pockets, bonus pieces, the rail).
	var order := 0
	var payout := 0
	## Share of the shots it caught, and the half-width of its 95% interval.
	var rate := 0.0
	var ci95 := 0.0
	## Its share of every ball given back.
	var share := 0.0


## The rows for `report` on `level` (empty for an empty report or one counted on other
## pockets).
static func rows(report: Dictionary, level: BoardLevel) -> Array[Row]:
	var out: Array[Row] = []
	var pockets: Array = report.get("pockets", [])
	if report.is_empty() or level == null:
		return out
	if pockets.size() != level.pockets.size() + level.bonus_pockets.size():
		return out
	var n := _whole(report.get("shots"))
	var returned := _whole(report.get("returned"))
	# Shares from the whole counts, not the rounded rates, so they add up to 1 exactly.
	var value := returned
	for pocket: Dictionary in pockets:
		value += _whole(pocket.get("hits")) * _whole(pocket.get("payout"))
	for p in pockets.size():
		var pocket: Dictionary = pockets[p]
		var item := _item_of(level, p)
		var row := _row(ItemNames.name_of(level, item), _whole(pocket.get("payout")))
		row.item = item
		_count(row, _whole(pocket.get("hits")), n, value)
		row.ci95 = AnalysisReport.number(pocket.get("ci95"))
		out.append(row)
	var back := _row(ROLLED_BACK, 1)
	_count(back, returned, n, value)
	back.ci95 = AnalysisStats.rate_half_width(returned, n)
	out.append(back)
	for i in out.size():
		out[i].order = i
	return out


## `table` by row name.
static func by_name(table: Array[Row]) -> Dictionary[String, Row]:
	var named: Dictionary[String, Row] = {}
	for row in table:
		named[row.name] = row
	return named


## The sum of the shares in `table` (1 when anything came back).
static func share_total(table: Array[Row]) -> float:
	var total := 0.0
	for row in table:
		total += row.share
	return total


## `table` sorted by `key` (SORT_KEYS), from the smallest when `ascending`; names sort in
## board order. `before` holds the earlier result's rows by name (for "before").
static func sorted(
	table: Array[Row], key: String, ascending: bool, before: Dictionary[String, Row]
) -> Array[Row]:
	var out := table.duplicate()
	out.sort_custom(
		func(a: Row, b: Row) -> bool:
			var first := _sort_value(a, key, before)
			var second := _sort_value(b, key, before)
			if first == second:
				return a.order < b.order
			return (first < second) == ascending
	)
	return out


static func _sort_value(row: Row, key: String, before: Dictionary[String, Row]) -> float:
	match key:
		"payout":
			return row.payout
		"rate":
			return row.rate
		"share":
			return row.share
		"before":
			return before[row.name].share if before.has(row.name) else -1.0
	return row.order


static func _row(row_name: String, payout: int) -> Row:
	var row := Row.new()
	row.name = row_name
	row.payout = payout
	return row


static func _count(row: Row, hits: int, n: int, value: int) -> void:
	row.rate = float(hits) / n if n > 0 else 0.0
	row.share = float(hits * row.payout) / value if value > 0 else 0.0


static func _whole(value: Variant) -> int:
	return roundi(AnalysisReport.number(value))


# The board item of report pocket `p`: the level's pockets first, then its bonus pockets.
static func _item_of(level: BoardLevel, p: int) -> Vector2i:
	if p < level.pockets.size():
		return BoardItems.make(BoardItems.Kind.POCKET, p)
	return BoardItems.make(BoardItems.Kind.BONUS, p - level.pockets.size())
