class_name PieceLegend
extends VBoxContainer
## The instructions panel's list of a board's pieces: one row per kind of piece the board
## has, a small drawing and one line. Only what the board has: Classic shows its pockets,
## Hanami its START pockets, ATTACKER and tulips.


func _init() -> void:
	add_theme_constant_override("separation", 4)
	mouse_filter = Control.MOUSE_FILTER_IGNORE


## Rebuilds the rows for `level`.
func show_pieces(level: BoardLevel) -> void:
	for child in get_children():
		remove_child(child)
		child.queue_free()
	for piece in BoardPieces.of(level):
		var row := HBoxContainer.new()
		row.mouse_filter = Control.MOUSE_FILTER_IGNORE
		row.add_theme_constant_override("separation", 12)
		row.add_child(PieceIcon.new(level, piece))
		var words := Label.new()
		words.text = BoardPieces.line(level, piece)
		words.autowrap_mode = TextServer.AUTOWRAP_WORD
		words.size_flags_horizontal = Control.SIZE_EXPAND_FILL
		words.vertical_alignment = VERTICAL_ALIGNMENT_CENTER
		words.add_theme_font_size_override("font_size", 14)
		words.custom_minimum_size = Vector2(300, 0)
		row.add_child(words)
		add_child(row)


## The lines shown, top to bottom (for tests).
func lines() -> PackedStringArray:
	var out := PackedStringArray()
	for row in get_children():
		out.append((row.get_child(1) as Label).text)
	return out
