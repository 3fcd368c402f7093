extends GutTest
## The jackpot banner's words: the jackpot's first round, each later round with its own number,
## and what the jackpot paid.


func _banner() -> Node2D:
	var banner: Node2D = JackpotBanner.new()
	add_child_autofree(banner)
	return banner


func test_a_later_round_is_announced_with_its_number() -> void:
	var banner := _banner()
	banner.show_round(Vector2(400, 400), 300.0, 3, 10)
	assert_eq(banner.caption(), "ROUND 3 / 10 feed the attacker!")


func test_the_first_round_comes_with_the_jackpot() -> void:
	var banner := _banner()
	banner.show_jackpot(Vector2(400, 400), 300.0, 10)
	assert_eq(banner.caption(), "ROUND 1 / 10 the attacker is open!")


# A trial's jackpot ended on "140 BALLS the jackpot paid" for three seconds: the end is a
# summary card now, with the rounds played and what the whole game has paid back.
func test_the_jackpot_ends_on_a_summary_card() -> void:
	var banner := _banner()
	banner.show_summary(Vector2(400, 400), 300.0, 10, 140, 312)
	assert_eq(
		banner.caption(),
		"+140 BALLS JACKPOT OVER 10 rounds played This game so far: 312 balls paid back"
	)
	assert_gt(banner.SUMMARY_SECONDS, 4.0, "long enough to read while play goes on")
	banner.show_summary(Vector2(400, 400), 300.0, 1, 1, 1)
	assert_string_contains(banner.caption(), "+1 BALL JACKPOT OVER 1 round played")
	banner.show_round(Vector2(400, 400), 300.0, 3, 10)
	assert_eq(banner.caption(), "ROUND 3 / 10 feed the attacker!", "a round has no card lines")
