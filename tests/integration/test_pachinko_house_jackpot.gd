extends GutTest
## A safety net for a new player (trial 5: a 20-minute first session could see no jackpot;
## trial 6: given on the first hit, at shot 18, it read as a giveaway): on a reel machine a
## game's first start-pocket hit after HOUSE_AFTER_SHOTS shots with no jackpot is a reach
## that lands one (said as any jackpot is, not as a gift: trial 8), once a board; a replay
## plays it back.

const GAME := preload("res://scenes/pachinko/pachinko_game.tscn")
const SaveData := preload("res://scripts/app/save_data.gd")
const FRAME := 1.0 / 60.0
const FEVER := "pachinko_fever"

var _kept_save: SaveData
var _kept_gift := false


func before_each() -> void:
	_kept_save = App.save_data
	_kept_gift = App.house_jackpots
	App.save_data = SaveData.new()  # a fresh save, in memory only: never written
	App.house_jackpots = true
	App.request_board("pachinko", "res://levels/pachinko/fever.board")


func after_each() -> void:
	App.save_data = _kept_save
	App.house_jackpots = _kept_gift
	App.request_board("pachinko", "res://levels/pachinko/classic.board")


func _start_pocket(level: BoardLevel) -> int:
	for i in level.bonus_pockets.size():
		if level.bonus_pockets[i].role == BonusPocketSpec.Role.START:
			return i
	return -1


# The game's first start-pocket hit, played until its reels stop.
func _first_hit(rules: PachinkoRules) -> void:
	rules.bonus.catch(_start_pocket(rules.level))
	for i in 600:
		rules.bonus.advance(FRAME)
		if rules.bonus.reel_spins > 0 and not rules.bonus.reels.busy():
			return


func test_the_first_hit_of_a_fresh_save_is_no_gift() -> void:
	var game := GAME.instantiate() as PachinkoGame
	add_child_autofree(game)
	await wait_process_frames(1)
	var rules := game.rules
	rules.start_game()
	assert_gte(rules.fire(60.0), 0)
	_first_hit(rules)
	assert_false(rules.bonus.last_spin_was_house(), "shot 1: the seed decides, no gift")
	assert_false(App.save_data.has_had_house_jackpot(FEVER))


func test_the_first_hit_after_the_shots_lands_a_jackpot_and_the_next_game_does_not() -> void:
	var game := GAME.instantiate() as PachinkoGame
	add_child_autofree(game)
	await wait_process_frames(1)
	var rules := game.rules
	rules.start_game()
	rules.ledger.shots = HouseJackpot.HOUSE_AFTER_SHOTS - 2
	assert_gte(rules.fire(60.0), 0)
	assert_false(rules.bonus.has_house_jackpot(), "one shot short: none yet")
	rules.run_steps(30)  # the launcher loads its next ball
	assert_gte(rules.fire(60.0), 0)
	assert_true(rules.bonus.has_house_jackpot(), "the threshold's shot grants it")
	_first_hit(rules)
	assert_eq(rules.bonus.jackpots, 1, "the next hit is a jackpot")
	assert_true(rules.bonus.rounds.active(), "its rounds are on")
	# trial 8: "First jackpot on the house!" read as a giveaway; it looks like any jackpot
	assert_string_contains(game.bonus_view().banner.caption(), "ROUND 1 / ")
	assert_false(game.bonus_view().banner.caption().contains("house"), "never said as a gift")
	assert_true(App.save_data.has_had_house_jackpot(FEVER), "kept in the save file")
	game.restart()
	var second := game.rules
	assert_ne(second, rules)
	second.start_game()
	second.ledger.shots = HouseJackpot.HOUSE_AFTER_SHOTS
	assert_gte(second.fire(60.0), 0)
	assert_false(second.bonus.has_house_jackpot(), "once a board: the next game has none")


func test_a_board_without_reels_and_the_tools_get_none() -> void:
	App.house_jackpots = false
	var game := GAME.instantiate() as PachinkoGame
	add_child_autofree(game)
	await wait_process_frames(1)
	assert_false(game.rules.bonus.has_house_jackpot(), "tests and tools: the seed decides")
	App.house_jackpots = true
	var level := BoardLoader.load_board("res://levels/pachinko/classic.board").level
	assert_false(HouseJackpot.offer(PachinkoRules.new(level, 1)), "Classic has no reels")


func test_a_replay_of_the_house_jackpot_plays_back_the_same() -> void:
	var level := BoardLoader.load_board("res://levels/pachinko/fever.board").level
	var rules := PachinkoRules.new(level, 5)
	rules.bonus.grant_house_jackpot()
	var recorder := ReplayRecorder.new()
	recorder.attach_pachinko(rules, 5)
	rules.start_game()
	rules.handle.set_power(60.0)
	rules.handle.grip()
	for i in 60 * 30:
		rules.advance(FRAME)
		recorder.note_frame()
		if rules.bonus.jackpots > 0 and rules.bonus.attacker_paid > 0:
			break
	assert_eq(rules.bonus.jackpots, 1, "the house's jackpot came")
	assert_gt(rules.bonus.attacker_paid, 0, "and its attacker caught a ball")
	var replay := recorder.finish()
	var text := ReplayWriter.write(replay)
	assert_string_contains(text, '["house",0]')
	var read: Replay = ReplayReader.read(text)["replay"]
	var played := ReplayPlayer.new(read, level).play_to_end()
	assert_true(played["match"], "played back: %s" % played)
	var without: Replay = ReplayReader.read(text.replace('["house",0]\n', ""))["replay"]
	var lost := ReplayPlayer.new(without, level).play_to_end()
	assert_false(lost["match"], "without the record the game goes another way")


func test_a_house_jackpot_granted_mid_game_is_recorded_at_its_step() -> void:
	var level := BoardLoader.load_board("res://levels/pachinko/fever.board").level
	var rules := PachinkoRules.new(level, 7)
	var recorder := ReplayRecorder.new()
	recorder.attach_pachinko(rules, 7)
	rules.start_game()
	for i in 30:
		rules.advance(FRAME)
		recorder.note_frame()
	rules.bonus.grant_house_jackpot()  # as HouseJackpot does at its shot
	var step := rules.world.step_count
	for i in 30:
		rules.advance(FRAME)
		recorder.note_frame()
	var text := ReplayWriter.write(recorder.finish())
	assert_string_contains(text, '["house",%d]' % step, "the grant at its step")
