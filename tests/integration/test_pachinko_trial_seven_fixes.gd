extends GutTest
## The seventh blind play trial's bugs (issue 41): the panel read "Down 100" and "0 now"
## behind the rules card and a number ahead of the tray during play; a jackpot's start
## stacked REACH!, a fading 444, a fading ROUND 1 / 10 and the round plaque; balls crossed
## the reach's big reels; Hanami's ATTACKER label was lost in the blossoms; Next machine
## from Windmills went round to Classic, cleared, not to Tulip Garden, unplayed; and a goal
## passed mid-jackpot said nothing for minutes.

const BoardSwap := preload("res://tests/helpers/pachinko_board_swap.gd")
const FRAME := 1.0 / 60.0

var _kept_save: RefCounted


func before_each() -> void:
	_kept_save = BoardSwap.begin(BoardSwap.CLASSIC)


func after_each() -> void:
	BoardSwap.end(_kept_save)


func _game(board: String) -> PachinkoGame:
	return BoardSwap.game(self, board)


func test_behind_the_card_the_panel_reads_the_trays_start() -> void:
	var game := _game("fever")
	await wait_process_frames(2)
	assert_eq(game.rules.state, PachinkoRules.State.INSTRUCTIONS, "the card is up")
	var start := game.rules.level.cup_start_balls
	var shown := game.stats_panel.shown_text()
	assert_string_contains(shown, "Won this game +0")
	assert_string_contains(shown, "Balls %d" % start)
	assert_false(shown.contains("Down"), shown)


func test_the_panels_now_is_the_trays_number_while_balls_pour_in() -> void:
	var game := _game("classic")
	await wait_process_frames(1)
	var rules := game.rules
	rules.start_game()
	# a pocket paid 5: the rules count them at once, the tray as they land
	game.cup.pour(5)
	rules.cup += 5
	rules.cup_changed.emit(rules.cup)
	game._process(FRAME)
	assert_lt(game.cup.count(), rules.balls_to_shoot, "balls still pouring in")
	var shown := game.stats_panel.shown_text()
	assert_string_contains(shown, "Balls %d" % game.cup.count(), "the tray's own number")
	for i in 240:
		game.cup._process(FRAME)
		game._process(FRAME)
	assert_eq(game.cup.count(), rules.balls_to_shoot, "all landed")
	shown = game.stats_panel.shown_text()
	assert_string_contains(shown, "Balls %d" % rules.balls_to_shoot, "and the panel with it")


func test_a_goal_passed_mid_jackpot_says_so_at_once() -> void:
	var game := _game("fever")
	await wait_process_frames(1)
	var rules := game.rules
	rules.start_game()
	rules.bonus.rounds.begin()
	var target := PachinkoGoals.tray_target(rules.level)
	rules.cup += target
	rules.cup_changed.emit(rules.cup)
	game.cup.catch_up(rules.balls_to_shoot)
	game._process(FRAME)
	assert_false(game.cleared_card().visible, "the card waits for the jackpot")
	assert_string_contains(game.stats_panel.shown_text(), "goal %d reached" % target)


# What announces something on the board now: the reach stage, the jackpot or round banner
# and the round's plaque.
func _announcements(view: BonusView) -> PackedStringArray:
	var up := PackedStringArray()
	if view.stage.is_on_stage():
		up.append("stage")
	if view.banner.is_drawn():
		up.append("banner: " + view.banner.caption())
	if view.fever.caption_shown():
		up.append("plaque: " + view.fever.caption())
	return up


func test_a_jackpot_announces_one_thing_at_a_time() -> void:
	var game := _game("fever")
	await wait_process_frames(1)
	var view := game.bonus_view()
	var machine := game.rules.bonus
	game.rules.start_game()
	machine.reels.start(PackedInt32Array([4, 4, 4]), 7)
	var seen := {}
	var stacked := PackedStringArray()
	for frame in 60 * 14:
		machine.advance(FRAME)
		view.stage._process(FRAME)
		view.banner._process(FRAME)
		var up := _announcements(view)
		for what in up:
			seen[what.get_slice(":", 0)] = true
		if up.size() > 1 and stacked.is_empty():
			stacked = up
	assert_true(machine.rounds.active(), "the jackpot's rounds are on")
	assert_eq(stacked, PackedStringArray(), "one announcement at a time")
	assert_eq(seen.keys().size(), 3, "stage, banner and plaque each had their turn: %s" % [seen])


func test_the_reach_stage_is_drawn_over_the_balls() -> void:
	var game := _game("fever")
	await wait_process_frames(1)
	var stage := game.bonus_view().stage
	var balls := game.board_view.get_node("Balls") as Node2D
	assert_gt(stage.z_index, balls.z_index, "the big reels cover a ball crossing them")
	assert_gt(stage.z_index, game.board_view.aim_preview().z_index, "and the aim's dots")


func test_the_attacker_label_sits_on_a_tag_of_its_own_clear_of_its_countdown() -> void:
	var game := _game("hanami")
	await wait_process_frames(1)
	var rules := game.rules
	rules.start_game()
	rules.bonus.rounds.begin()
	var found := 0
	for i in rules.level.bonus_pockets.size():
		var spec := rules.level.bonus_pockets[i]
		if spec.role != BonusPocketSpec.Role.ATTACKER:
			continue
		found += 1
		var tag := BonusPainter.label_rect(spec)
		assert_gte(tag.size.y, BonusPainter.LABEL_SIZE, "a tag behind the words: %s" % tag)
		assert_gte(tag.position.y, spec.position.y + spec.depth, "under the cup")
		assert_gt(BonusPainter.LABEL_TAG.a, 0.8, "dark enough to read over any art")
		if rules.bonus.is_open(i):
			var countdown := game.bonus_view().art.countdown_rect(i)
			assert_false(
				tag.intersects(countdown), "%s clear of the countdown %s" % [tag, countdown]
			)
	assert_eq(found, 1, "Hanami has its attacker")


func test_next_machine_goes_on_to_a_board_not_played_yet() -> void:
	# trial 7: Classic, Fever, Hanami played (two cleared), Windmills just cleared
	for id: String in ["classic", "fever", "hanami", "windmills"]:
		App.save_data.record_pachinko_balls("pachinko_" + id, 5)
	for id: String in ["classic", "fever", "windmills"]:
		App.save_data.note_pachinko_cleared("pachinko_" + id)
	var windmills := BoardLoader.load_board("res://levels/pachinko/windmills.board").level
	assert_eq(MachineGoal.next_board_path(windmills), "res://levels/pachinko/tulips.board")
	App.save_data.record_pachinko_balls("pachinko_tulips", 5)
	assert_eq(
		MachineGoal.next_board_path(windmills),
		"res://levels/pachinko/hanami.board",
		"all played: the first not cleared"
	)


func test_next_index_prefers_unplayed_then_uncleared_then_the_next() -> void:
	var none := PackedByteArray([0, 0, 0])
	var all := PackedByteArray([1, 1, 1])
	assert_eq(MachineGoal.next_index(0, none, none), 1, "a fresh player: the next")
	assert_eq(MachineGoal.next_index(2, none, none), 0, "round from the last")
	assert_eq(MachineGoal.next_index(0, PackedByteArray([1, 1, 0]), all), 2)
	assert_eq(MachineGoal.next_index(0, all, PackedByteArray([1, 1, 0])), 2)
	assert_eq(MachineGoal.next_index(1, all, all), 2, "all cleared: the next")
	assert_eq(MachineGoal.next_index(-1, none, none), 0, "not in the list: the first")
	assert_eq(MachineGoal.next_index(0, PackedByteArray(), PackedByteArray()), -1)
