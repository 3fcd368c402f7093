extends GutTest
## The jackpot banner's words: the jackpot's first round, each later round with its own number,
## and what the jackpot paid.

const BANNER := preload("res://scenes/pachinko/bonus/jackpot_banner.gd")


func _banner() -> Node2D:
	var banner: Node2D = BANNER.new()
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


func test_the_total_names_the_balls_paid() -> void:
	var banner := _banner()
	banner.show_total(Vector2(400, 400), 300.0, 1)
	assert_eq(banner.caption(), "1 BALL the jackpot paid")
	banner.show_total(Vector2(400, 400), 300.0, 140)
	assert_eq(banner.caption(), "140 BALLS the jackpot paid")
