extends GutTest
## The instructions explain each board's own pieces: a drawing and one line per kind of
## piece the board has, and nothing about pieces it does not have.

const PANEL := "res://scenes/pachinko/instructions_panel.tscn"


func _lines_for(id: String) -> PackedStringArray:
	var panel := (load(PANEL) as PackedScene).instantiate() as InstructionsPanel
	add_child_autofree(panel)
	var level := BoardLoader.load_board("res://levels/pachinko/%s.board" % id).level
	panel.show_start(level)
	var legend := panel.legend() as VBoxContainer
	assert_true(legend.visible)
	for row in legend.get_children():
		assert_eq(row.get_child_count(), 2, "a drawing and a line")
		var icon := row.get_child(0) as Control
		assert_gt(icon.custom_minimum_size.x, 0.0, "the drawing has room")
	return (legend as PieceLegend).lines()


func _joined(lines: PackedStringArray) -> String:
	return "\n".join(lines)


func test_classic_explains_only_its_pockets() -> void:
	var lines := _lines_for("classic")
	assert_eq(lines.size(), 1)
	# rules 5: the side pair pays 10, the top 3, the low pair 2 (see test_board_levels)
	assert_string_contains(lines[0], "Pocket: a ball that drops in pays 2 to 10 balls")


func test_hanami_explains_its_start_pockets_attacker_and_tulips() -> void:
	var text := _joined(_lines_for("hanami"))
	assert_string_contains(text, "START pocket")
	assert_string_contains(text, "ATTACKER")
	assert_string_contains(text, "Tulip")
	assert_false(text.contains("Pocket: "), "Hanami has no plain pockets")


func test_tulip_garden_explains_its_pockets_and_tulips_only() -> void:
	var text := _joined(_lines_for("tulips"))
	assert_string_contains(text, "Pocket: ")
	assert_string_contains(text, "Tulip: pays 1 to 4 balls")
	assert_false(text.contains("START"))
	assert_false(text.contains("ATTACKER"))


func test_windmills_explains_its_windmills_with_a_drawing() -> void:
	var lines := _lines_for("windmills")
	var text := _joined(lines)
	assert_string_contains(text, "Windmill: ")
	assert_string_contains(text, "a red hub turns by itself, a brass one only when balls hit it")
	assert_string_contains(text, "Pocket: ")
	assert_eq(lines[0].left(9), "Windmill:", "balls meet the windmills before the pockets")


func test_boards_without_windmills_do_not_mention_them() -> void:
	for id: String in ["classic", "tulips", "fever", "hanami"]:
		assert_false(_joined(_lines_for(id)).contains("Windmill"), id)


func test_a_board_with_only_free_wheels_says_they_turn_when_hit() -> void:
	var level := (
		BoardLoader.load_board("res://levels/pachinko/windmills.board").level.duplicate_level()
	)
	for spec in level.windmills:
		spec.free_spin = true
	var line := BoardPieces.line(level, BoardPieces.Piece.WINDMILL)
	assert_string_contains(line, "it only turns when balls hit it")
	assert_false(line.contains("red hub"))


func test_the_game_over_box_leaves_the_pieces_out() -> void:
	var panel := (load(PANEL) as PackedScene).instantiate() as InstructionsPanel
	add_child_autofree(panel)
	var level := BoardLoader.load_board("res://levels/pachinko/fever.board").level
	panel.show_start(level)
	panel.show_game_over(level, {"game_shots": 3, "game_payouts": 4}, 0, false)
	assert_false(panel.legend().visible)


func test_mixed_payouts_read_as_a_range() -> void:
	var level := (
		BoardLoader.load_board("res://levels/pachinko/classic.board").level.duplicate_level()
	)
	for spec in level.pockets:
		spec.payout = 6
	level.pockets[0].payout = 2
	assert_string_contains(BoardPieces.line(level, BoardPieces.Piece.POCKET), "2 to 6 balls")
