extends GutTest
## The payout pour: every paid ball reaches the cup, in order, however big the payout.


func _run(pour: PayoutPour, seconds: float) -> int:
	var arrived := 0
	for i in int(seconds * 60.0):
		arrived += pour.advance(1.0 / 60.0)
	return arrived


func test_every_paid_ball_lands_in_the_cup() -> void:
	for balls: int in [1, 7, 20, 21, 153, 1000]:
		var pour := PayoutPour.new()
		pour.pour(balls, 100.0, 90.0)
		assert_eq(pour.pending(), balls, "%d balls on their way" % balls)
		assert_lte(pour.drops.size(), PayoutPour.MAX_DROPS)
		var arrived := _run(pour, 4.0)
		assert_eq(arrived, balls, "all %d landed" % balls)
		assert_eq(pour.landed, balls)
		assert_eq(pour.pending(), 0)
		assert_true(pour.drops.is_empty())


func test_a_second_payout_pours_after_the_first() -> void:
	var pour := PayoutPour.new()
	pour.pour(20, 100.0, 90.0)
	pour.pour(5, 100.0, 90.0)
	var first_landed := 0
	for i in 600:
		pour.advance(1.0 / 60.0)
		if pour.landed > 0 and first_landed == 0:
			first_landed = pour.landed
	assert_eq(first_landed, 1, "the first payout's first drop lands first")
	assert_eq(pour.landed, 25)


func test_nothing_paid_pours_nothing() -> void:
	var pour := PayoutPour.new()
	pour.pour(0, 100.0, 90.0)
	pour.pour(-3, 100.0, 90.0)
	assert_eq(pour.pending(), 0)
	assert_eq(_run(pour, 1.0), 0)
