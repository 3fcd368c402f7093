extends GutTest
## Trial 8 (issue 41), "stakes, not a firehose": Fever went 59 to 1463 balls in five minutes
## (one jackpot paid 714 and a second began at once) while its goal asked for 127. On the
## reel machines a jackpot aimed at the attacker pays 100 to 250 balls, a jackpot back to
## back with the last is uncommon (at most 1 in 5), and the goal is more than the balls
## streaming brings but within what a jackpot brings. The catches a round and a jackpot's
## net were measured with `tools/jackpot_sample.gd --count=20 --aim` (rules 8).

## Board -> the attacker's catches a round when the handle is held in its band (measured:
## Fever 192.6 balls over 10 rounds at 4 a catch, Hanami 160.5 at 3).
const AIMED_CATCHES := {"fever": 4.8, "hanami": 5.35}
## Board -> the balls held from an aimed jackpot's start to its end, on average (measured).
const AIMED_NET := {"fever": 81.0, "hanami": 117.0}


func _level(board: String) -> BoardLevel:
	return BoardLoader.load_board("res://levels/pachinko/%s.board" % board).level


func _attacker(level: BoardLevel) -> BonusPocketSpec:
	for spec in level.bonus_pockets:
		if spec.role == BonusPocketSpec.Role.ATTACKER:
			return spec
	return null


func test_an_aimed_jackpot_pays_100_to_250_balls() -> void:
	for board: String in AIMED_CATCHES:
		var attacker := _attacker(_level(board))
		var catches: float = minf(AIMED_CATCHES[board], attacker.open_catches)
		var paid := catches * attacker.payout * JackpotRounds.ROUNDS
		assert_between(paid, 100.0, 250.0, "%s: an aimed jackpot pays %.0f" % [board, paid])


func test_a_jackpot_back_to_back_is_at_most_one_in_five() -> void:
	for board: String in AIMED_CATCHES:
		var level := _level(board)
		for spec in level.bonus_pockets:
			if spec.role != BonusPocketSpec.Role.START:
				continue
			# the spins queued during the rounds (at most MAX_QUEUED) run as they end
			var odds := 1.0 / (spec.symbols * spec.symbols)
			var again := 1.0 - pow(1.0 - odds, BonusMachine.MAX_QUEUED)
			assert_lte(again, 0.2, "%s: a jackpot again %.2f" % [board, again])


func test_a_reel_machines_goal_is_in_a_jackpots_reach_and_more_than_a_trickle() -> void:
	for board: String in AIMED_NET:
		var level := _level(board)
		var needed := PachinkoGoals.tray_target(level) - level.cup_start_balls
		var net: float = AIMED_NET[board]
		assert_gte(needed, 50, "%s: the goal asks for %d balls won" % [board, needed])
		assert_lte(
			needed, net * 1.2, "%s: one aimed jackpot (+%.0f) nearly gets there" % [board, net]
		)
