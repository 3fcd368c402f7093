extends GutTest
## The fourth blind play trial's small fixes (issue 41): the reminder after R sits inside the
## board's area under its name plate; the jackpot's round caption is clear of the reels and
## an open attacker's countdown reads in one piece on a plaque of its own; dragging the
## handle's dial left turns it down, as the Left key does; the cards explain the power bar's
## arrow, REACH and where a strong shot goes; Windmills' card no longer calls a ×1 pocket rich.

const BoardSwap := preload("res://tests/helpers/pachinko_board_swap.gd")

var _kept_save: RefCounted
var _kept_skip := false


func before_each() -> void:
	_kept_save = App.save_data
	_kept_skip = App.skip_seen_rules_cards
	App.save_data = SaveData.new()  # in memory only: never written


func after_each() -> void:
	App.save_data = _kept_save
	App.skip_seen_rules_cards = _kept_skip
	App.request_board("pachinko", "res://levels/pachinko/classic.board")


func _game(board: String) -> PachinkoGame:
	return BoardSwap.game(self, board)


func test_the_reminder_after_r_keeps_inside_the_board_and_off_its_name_plate() -> void:
	App.skip_seen_rules_cards = true
	for board: String in ["windmills", "fever"]:
		var game := _game(board)
		await wait_process_frames(2)
		App.note_pachinko_rules_seen(game.rules.level.board_id)
		game.restart()
		await wait_process_frames(2)
		var line := game.reminder().get_rect()
		assert_true(game.reminder().visible, board)
		assert_true(
			game.board_area().encloses(line), "%s: %s in %s" % [board, line, game.board_area()]
		)
		assert_false(
			line.intersects(game.name_plate_rect()),
			"%s: %s clear of the name plate %s" % [board, line, game.name_plate_rect()]
		)


func test_the_round_caption_is_clear_of_the_reels() -> void:
	var game := _game("fever")
	await wait_process_frames(1)
	game.rules.start_game()
	game.rules.bonus.rounds.begin()
	var caption := game.bonus_view().fever.caption_rect()
	var reels := BonusGeometry.reel_window(game.rules.level).grow(BonusGeometry.REEL_FRAME_RADIUS)
	assert_false(caption.has_area() and caption.intersects(reels), "%s over %s" % [caption, reels])
	assert_true(caption.has_area())


func test_the_attackers_countdown_is_one_piece_clear_of_the_start_pocket() -> void:
	var game := _game("fever")
	await wait_process_frames(1)
	var rules := game.rules
	rules.start_game()
	rules.bonus.rounds.begin()
	var level := rules.level
	var art := game.bonus_view().art
	for i in level.bonus_pockets.size():
		if level.bonus_pockets[i].role != BonusPocketSpec.Role.ATTACKER:
			continue
		assert_true(rules.bonus.is_open(i), "the round opened the attacker")
		assert_string_contains(art.countdown_text(i), "s · ")
		var plaque := art.countdown_rect(i)
		for other in level.bonus_pockets:
			if other.role == BonusPocketSpec.Role.START:
				var body := Rect2(
					other.position - Vector2(other.width * 0.5 + 5.0, 12.0),
					Vector2(other.width + 10.0, other.depth + 18.0)
				)
				assert_false(
					plaque.intersects(body), "%s clear of the START pocket %s" % [plaque, body]
				)
	assert_gt(art.countdown_layer().z_index, 0, "drawn over the board's other pieces")


func test_dragging_the_dial_left_turns_the_handle_down() -> void:
	var game := _game("classic")
	await wait_process_frames(1)
	var rules := game.rules
	rules.start_game()
	var controls := PachinkoInput.new()
	var before := rules.handle.power
	controls.begin_handle_drag(rules, Vector2(500, 300))
	var motion := InputEventMouseMotion.new()
	motion.position = Vector2(480, 300)
	controls.handle_pointer(rules, motion, game)
	assert_lt(rules.handle.power, before, "left is weaker, as the Left key")
	motion.position = Vector2(520, 300)
	controls.handle_pointer(rules, motion, game)
	assert_gt(rules.handle.power, before, "right is stronger")
	rules.handle.let_go()


func test_the_cards_explain_the_arrow_reach_and_a_strong_shot() -> void:
	var game := _game("fever")
	await wait_process_frames(1)
	var body := (
		(game.instructions.get_node("Card/Margin/Box/Body") as RichTextLabel).get_parsed_text()
	)
	assert_string_contains(body, "farther round the top")
	assert_string_contains(body, "arrow")
	var start := BoardPieces.line(game.rules.level, BoardPieces.Piece.START)
	assert_string_contains(start, "REACH")


func test_no_card_calls_a_one_ball_pocket_rich() -> void:
	var loaded := BoardLoader.load_board("res://levels/pachinko/windmills.board")
	var pays: Array[int] = []
	for pocket in loaded.level.pockets:
		pays.append(pocket.payout)
	assert_true(pays.has(1), "Windmills has a ×1 pocket")
	assert_false(loaded.level.description.contains("three rich"), loaded.level.description)
