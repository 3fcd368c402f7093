extends GutTest
## A decision during a jackpot (trial 5: once a stream paid there was little to decide): on
## Fever and Hanami the attacker is fed best by a stronger handle than the default 60, the
## band AttackerBands names, and while the rounds last the launcher marks it and says so.

const GAME := preload("res://scenes/pachinko/pachinko_game.tscn")
const DEFAULT_POWER := 60


func after_each() -> void:
	App.request_board("pachinko", "res://levels/pachinko/classic.board")


# The attacker's catches over one jackpot streamed at `power` (as tools/attacker_band.gd).
func _catches(level: BoardLevel, power: int) -> int:
	var rules := PachinkoRules.new(level, 1)
	rules.start_game()
	rules.cup = 100000
	rules.handle.set_power(power)
	rules.handle.grip()
	rules.bonus.rounds.begin()
	for i in int(200.0 / rules.step_seconds()):
		rules.step()
		if not rules.bonus.rounds.active():
			break
	var payout := 1
	for spec in level.bonus_pockets:
		if spec.role == BonusPocketSpec.Role.ATTACKER:
			payout = spec.payout
	return rules.bonus.jackpot_paid / payout


func test_the_attacker_is_fed_in_its_band_far_better_than_at_the_default_power() -> void:
	for board in ["fever", "hanami"]:
		var level := BoardLoader.load_board("res://levels/pachinko/%s.board" % board).level
		var band := AttackerBands.band_of(level)
		assert_gt(band.x, DEFAULT_POWER + 10, "%s: the band %s is away from 60" % [board, band])
		var middle := (band.x + band.y) / 2
		var in_band := _catches(level, middle)
		var at_default := _catches(level, DEFAULT_POWER)
		assert_gt(
			in_band,
			at_default * 2,
			"%s: %d catches at %d, %d at 60" % [board, in_band, middle, at_default]
		)


func test_the_launcher_marks_the_band_and_says_it_while_the_rounds_last() -> void:
	App.request_board("pachinko", "res://levels/pachinko/fever.board")
	var game := GAME.instantiate() as PachinkoGame
	add_child_autofree(game)
	await wait_process_frames(1)
	var rules := game.rules
	rules.start_game()
	var launcher := game.launcher
	assert_eq(launcher.aim_band(), Vector2i.ZERO, "no band before a jackpot")
	rules.bonus.rounds.begin()
	assert_eq(launcher.aim_band(), Vector2i(75, 85))
	# trial 9: single shots at the old "power 75–85" caught nothing; the band is the stream's
	assert_eq(launcher.hint_text(), "Feed the attacker:\nstream at 75–85")
	rules.bonus.rounds.current_round = JackpotRounds.ROUNDS
	rules.bonus.rounds.end_round()
	assert_eq(launcher.aim_band(), Vector2i.ZERO, "gone with the last round")
	assert_string_contains(launcher.hint_text(), "One shot", "the controls hint is back")


func test_a_board_without_a_band_says_nothing() -> void:
	var level := BoardLoader.load_board("res://levels/pachinko/classic.board").level
	assert_eq(AttackerBands.band_of(level), Vector2i.ZERO)
	assert_eq(AttackerBands.words(Vector2i.ZERO), "")
