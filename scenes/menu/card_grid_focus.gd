class_name CardGridFocus
extends RefCounted
## Focus neighbours for the level select's cards, so the arrows and the d-pad move card to
## card: Up / Down to the card above or below (the nearest one when that row is shorter),
## across the gap between the shipped boards and My boards; Left / Right along a row and on to
## the next or previous row; Tab in the same reading order. The top row's Up is left to Godot
## (it finds the header's buttons); the last row's Down stays put.


## Links every card of `sections` (each a list of cards in reading order, laid out in rows of
## `columns`) to its neighbours.
static func link(sections: Array, columns: int) -> void:
	columns = maxi(columns, 1)
	var rows: Array[Array] = []
	var flat: Array[Control] = []
	for section: Array in sections:
		var row: Array[Control] = []
		for card: Control in section:
			flat.append(card)
			row.append(card)
			if row.size() == columns:
				rows.append(row)
				row = []
		if not row.is_empty():
			rows.append(row)
	for r in rows.size():
		var row: Array[Control] = rows[r]
		for c in row.size():
			var card := row[c]
			card.focus_neighbor_top = (
				_path(card, _nearest(rows[r - 1], c)) if r > 0 else NodePath()
			)
			card.focus_neighbor_bottom = _path(
				card, _nearest(rows[r + 1], c) if r + 1 < rows.size() else card
			)
	for i in flat.size():
		var card := flat[i]
		var before := flat[i - 1] if i > 0 else card
		var after := flat[i + 1] if i + 1 < flat.size() else card
		card.focus_neighbor_left = _path(card, before)
		card.focus_neighbor_right = _path(card, after)
		card.focus_previous = _path(card, before) if i > 0 else NodePath()
		card.focus_next = _path(card, after) if i + 1 < flat.size() else NodePath()


# The card of `row` in column `column`, or its last when the row is shorter.
static func _nearest(row: Array[Control], column: int) -> Control:
	return row[mini(column, row.size() - 1)]


static func _path(from: Control, to: Control) -> NodePath:
	return from.get_path_to(to)
