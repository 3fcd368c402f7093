extends GutTest
## A decision that changes during play (issue 41, trial 7): when a tulip opens the launcher
## marks the strengths that reach it on the bar and the dial and says "Tulip open: power
## 55–65"; when it shuts the mark goes; during a jackpot's rounds the attacker's band comes
## first (TulipBands, measured with tools/tulip_band.gd).

const BoardSwap := preload("res://tests/helpers/pachinko_board_swap.gd")

var _kept_save: RefCounted


func before_each() -> void:
	_kept_save = BoardSwap.begin(BoardSwap.CLASSIC)


func after_each() -> void:
	BoardSwap.end(_kept_save)


func _game(board: String) -> PachinkoGame:
	return BoardSwap.game(self, board)


func _tulips(level: BoardLevel) -> Array[int]:
	var found: Array[int] = []
	for i in level.bonus_pockets.size():
		if level.bonus_pockets[i].role == BonusPocketSpec.Role.TULIP:
			found.append(i)
	return found


func test_every_shipped_tulip_has_a_band_inside_the_bar() -> void:
	for board: String in ["tulips", "fever", "hanami"]:
		var level := BoardLoader.load_board("res://levels/pachinko/%s.board" % board).level
		var tulips := _tulips(level)
		assert_gt(tulips.size(), 0, board)
		for i in tulips:
			var band := TulipBands.band_of(level, i)
			assert_ne(band, Vector2i.ZERO, "%s: tulip %d has a band" % [board, i])
			assert_true(
				0 <= band.x and band.x <= band.y and band.y <= 100, "%s: %s" % [board, band]
			)


func test_an_open_tulip_marks_its_band_and_a_shut_one_clears_it() -> void:
	var game := _game("tulips")
	await wait_process_frames(1)
	var rules := game.rules
	rules.start_game()
	var tulip := _tulips(rules.level)[0]
	assert_eq(game.launcher.aim_band(), Vector2i.ZERO, "nothing open, nothing marked")
	rules.bonus.catch(tulip)  # a catch opens it
	assert_true(rules.bonus.is_open(tulip))
	var band := TulipBands.band_of(rules.level, tulip)
	assert_eq(game.launcher.aim_band(), band)
	assert_string_contains(game.launcher.hint_text(), "Tulip open:")
	assert_string_contains(game.launcher.hint_text(), "power %d–%d" % [band.x, band.y])
	rules.bonus.catch(tulip)  # the next catch shuts it
	assert_eq(game.launcher.aim_band(), Vector2i.ZERO, "shut: the mark goes")
	assert_false(game.launcher.hint_text().contains("Tulip"), game.launcher.hint_text())


func test_the_last_tulip_opened_is_marked_and_the_attacker_comes_first() -> void:
	var game := _game("hanami")
	await wait_process_frames(1)
	var rules := game.rules
	rules.start_game()
	var tulips := _tulips(rules.level)
	rules.bonus.catch(tulips[0])
	rules.bonus.catch(tulips[2])
	assert_eq(game.launcher.aim_band(), TulipBands.band_of(rules.level, tulips[2]), "the last")
	rules.bonus.catch(tulips[2])  # shut: back to the one still open
	assert_eq(game.launcher.aim_band(), TulipBands.band_of(rules.level, tulips[0]))
	rules.bonus.rounds.begin()
	assert_eq(game.launcher.aim_band(), AttackerBands.band_of(rules.level), "rounds: attacker")
	assert_string_contains(game.launcher.hint_text(), "attacker")


func test_aim_with_nothing_open_is_nothing() -> void:
	var level := BoardLoader.load_board("res://levels/pachinko/fever.board").level
	var none: Array[int] = []
	assert_eq(TulipBands.aim(level, false, none)["band"], Vector2i.ZERO)
	assert_eq(TulipBands.aim(level, true, none)["band"], AttackerBands.band_of(level))
	assert_eq(TulipBands.words(Vector2i(55, 65)), "Tulip open: power 55–65")
