extends GutTest
## The pachinko ledger: where every ball went. The side panel's "this game" figures, the
## autoplay's JSON and the accounting check all read these counts, so a payout booked to the
## wrong pocket or a game's figures taken from the wrong start shows up on screen.

const COUNTERS: Array[String] = [
	"given", "paid", "shots", "drained", "won", "returned", "nudges", "vanished"
]


# A ledger of 3 pockets whose every counter holds a different number (given 10, paid 20...).
func _filled() -> PachinkoLedger:
	var ledger := PachinkoLedger.new(3)
	for i in COUNTERS.size():
		ledger.set(COUNTERS[i], (i + 1) * 10)
	ledger.pocket_hits = PackedInt32Array([1, 2, 3])
	ledger.pocket_payouts = PackedInt32Array([10, 20, 30])
	return ledger


func test_a_new_ledger_has_a_zero_per_pocket() -> void:
	var ledger := PachinkoLedger.new(3)
	assert_eq(ledger.pocket_hits, PackedInt32Array([0, 0, 0]))
	assert_eq(ledger.pocket_payouts, PackedInt32Array([0, 0, 0]))
	var none := PachinkoLedger.new(-1)
	assert_eq(none.pocket_hits.size(), 0, "a board without pockets")
	assert_eq(none.pocket_payouts.size(), 0)


func test_a_win_pays_its_pocket() -> void:
	var ledger := PachinkoLedger.new(3)
	ledger.record_win(1, 15)
	ledger.record_win(1, 5)
	ledger.record_win(2, 7)
	assert_eq(ledger.won, 3)
	assert_eq(ledger.paid, 27)
	assert_eq(ledger.pocket_hits, PackedInt32Array([0, 2, 1]))
	assert_eq(ledger.pocket_payouts, PackedInt32Array([0, 20, 7]))


func test_the_first_and_last_pocket_are_booked_and_no_other() -> void:
	var ledger := PachinkoLedger.new(3)
	ledger.record_win(0, 4)
	ledger.record_win(2, 6)
	assert_eq(ledger.pocket_hits, PackedInt32Array([1, 0, 1]))
	assert_eq(ledger.pocket_payouts, PackedInt32Array([4, 0, 6]))
	ledger.record_win(3, 9)
	ledger.record_win(-1, 8)
	assert_eq(ledger.pocket_hits, PackedInt32Array([1, 0, 1]), "unknown pockets book nothing")
	assert_eq(ledger.won, 4, "but the balls still count as won")
	assert_eq(ledger.paid, 27, "and their payouts as paid")


func test_a_copy_keeps_every_count_and_moves_on_alone() -> void:
	var ledger := _filled()
	var copy: PachinkoLedger = ledger.copy()
	for key in COUNTERS:
		assert_eq(copy.get(key), ledger.get(key), key)
	assert_eq(copy.pocket_hits, PackedInt32Array([1, 2, 3]))
	assert_eq(copy.pocket_payouts, PackedInt32Array([10, 20, 30]))
	ledger.record_win(0, 5)
	assert_eq(copy.won, 50, "a later win is not in the copy")
	assert_eq(copy.pocket_hits, PackedInt32Array([1, 2, 3]))
	assert_eq(copy.pocket_payouts, PackedInt32Array([10, 20, 30]))


func test_this_games_figures_are_the_counts_since_it_started() -> void:
	var start := _filled()
	var now: PachinkoLedger = start.copy()
	for i in COUNTERS.size():
		now.set(COUNTERS[i], now.get(COUNTERS[i]) + i + 1)
	now.pocket_hits = PackedInt32Array([4, 2, 5])
	now.pocket_payouts = PackedInt32Array([40, 20, 33])
	var game: PachinkoLedger = now.since(start)
	for i in COUNTERS.size():
		assert_eq(game.get(COUNTERS[i]), i + 1, COUNTERS[i])
	assert_eq(game.pocket_hits, PackedInt32Array([3, 0, 2]))
	assert_eq(game.pocket_payouts, PackedInt32Array([30, 0, 3]))
	assert_eq(now.pocket_hits, PackedInt32Array([4, 2, 5]), "the session's counts stay")
	assert_eq(now.won, 55)


func test_since_a_start_with_fewer_pockets_keeps_the_new_pockets_whole() -> void:
	var start := PachinkoLedger.new(1)
	start.record_win(0, 3)
	var now := PachinkoLedger.new(2)
	now.record_win(0, 3)
	now.record_win(0, 3)
	now.record_win(1, 9)
	var game: PachinkoLedger = now.since(start)
	assert_eq(game.pocket_hits, PackedInt32Array([1, 1]))
	assert_eq(game.pocket_payouts, PackedInt32Array([3, 9]))


func test_the_balls_balance_only_when_every_one_is_somewhere() -> void:
	var ledger := PachinkoLedger.new(1)
	ledger.given = 10
	ledger.record_win(0, 5)  # 15 balls in all, 1 of them won
	ledger.drained = 2
	assert_true(ledger.balances(9, 1, 2), "9 in the cup, 1 loaded, 2 in play, 2 drained, 1 won")
	assert_false(ledger.balances(10, 1, 2), "a ball too many in the cup")
	assert_false(ledger.balances(9, 0, 2), "the loaded ball missing")
	assert_false(ledger.balances(9, 1, 1), "a ball in play missing")
	assert_false(ledger.balances(8, 1, 2), "a ball lost")
	ledger.drained = 3
	assert_false(ledger.balances(9, 1, 2), "a drained ball too many")


func test_the_payout_ratio_counts_only_shots_that_reached_the_field() -> void:
	var ledger := PachinkoLedger.new(1)
	assert_eq(ledger.field_shots(), 0)
	assert_eq(ledger.payout_ratio(), 0.0, "no shot yet")
	ledger.shots = 10
	ledger.returned = 2
	ledger.paid = 12
	assert_eq(ledger.field_shots(), 8)
	assert_eq(ledger.payout_ratio(), 1.5, "12 paid over 8 shots")
	ledger.returned = 10
	assert_eq(ledger.field_shots(), 0)
	assert_eq(ledger.payout_ratio(), 0.0, "every shot rolled back")
	ledger.returned = 12
	assert_eq(ledger.field_shots(), 0, "never below zero")


func test_the_snapshot_the_panel_and_autoplay_read() -> void:
	var ledger := _filled()
	ledger.shots = 9  # 9 launched, 6 returned: 3 reached the field, 20 paid
	ledger.returned = 6
	assert_eq(
		ledger.to_dict(),
		{
			"given": 10,
			"shots": 9,
			"pocket_hits": [1, 2, 3],
			"pocket_payouts": [10, 20, 30],
			"payouts": 20,
			"gold_balls": 0,
			"won": 50,
			"drained": 40,
			"returned": 6,
			"nudges": 70,
			"vanished": 80,
			"payout_ratio": 6.667,
		}
	)


func test_a_new_session_starts_from_nothing() -> void:
	var fresh := PachinkoLedger.new(2).to_dict()
	for key: String in ["given", "shots", "payouts", "won", "drained", "returned", "nudges"]:
		assert_eq(fresh[key], 0, key)
	assert_eq(fresh["vanished"], 0)
	assert_eq(fresh["pocket_hits"], [0, 0])
	assert_eq(fresh["payout_ratio"], 0.0)


func test_the_first_shot_to_reach_the_field_sets_the_ratio() -> void:
	var ledger := PachinkoLedger.new(1)
	ledger.shots = 1
	ledger.record_win(0, 6)
	assert_eq(ledger.payout_ratio(), 6.0, "one shot, six balls back")


func test_gold_pin_balls_balance_and_count_in_the_ratio_but_not_as_pocket_pay() -> void:
	var ledger := PachinkoLedger.new(1)
	ledger.given = 10
	ledger.shots = 4
	ledger.record_win(0, 6)
	ledger.gold = 2
	# 10 given + 6 paid + 2 gold = 18: 4 shot (1 won, 3 drained), 14 in the cup
	ledger.drained = 3
	assert_true(ledger.balances(14, 0, 0))
	assert_eq(ledger.payout_ratio(), 2.0, "(6 + 2) balls back over 4 shots")
	assert_eq(ledger.to_dict()["payouts"], 6, "pocket pay alone")
	assert_eq(ledger.since(PachinkoLedger.new(1)).get("gold"), 2)
