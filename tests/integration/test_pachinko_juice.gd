extends GutTest
## Lights and juice: a struck pin glows and fades (one canvas item for every lit pin), paid
## balls pour into the cup, and balls are drawn larger than their physics with a dark rim.

const GAME := "res://scenes/pachinko/pachinko_game.tscn"


func _game() -> PachinkoGame:
	var game := (load(GAME) as PackedScene).instantiate() as PachinkoGame
	add_child_autofree(game)
	return game


func test_a_struck_pin_lights_up_and_fades() -> void:
	var game := _game()
	var rules := game.get("rules") as PachinkoRules
	var lights := game.get_node("BoardView/PinLights")
	assert_not_null(lights, "one pin-lights layer")
	assert_eq(lights.get_child_count(), 0, "no node per pin")
	rules.world.pin_hit.emit(0, 7, 400.0)
	rules.world.pin_hit.emit(0, 9, 40.0)
	assert_eq(lights.glow_of(7), 1.0, "a hard hit lights fully")
	assert_almost_eq(float(lights.glow_of(9)), 0.35, 0.001, "a tap still shows")
	lights._process(0.2)
	assert_lt(float(lights.glow_of(7)), 1.0, "fading")
	assert_gt(float(lights.glow_of(7)), 0.0)
	lights._process(1.0)
	assert_eq(lights.glow_of(7), 0.0, "out")
	assert_false(lights.is_processing(), "asleep when nothing is lit")


func test_the_ball_layer_sits_above_the_lights() -> void:
	var game := _game()
	var view := game.get_node("BoardView")
	assert_lt(
		view.get_node("PinLights").get_index(), view.get_node("Balls").get_index(), "balls on top"
	)


func test_paid_balls_pour_into_the_cup() -> void:
	var game := _game()
	var cup := game.cup
	cup.pour(4)
	assert_eq(cup.pouring(), 4, "four balls on their way")
	for i in 60:
		cup._process(1.0 / 60.0)
	assert_eq(cup.pouring(), 0, "all landed within a second")
	cup.set_count(10 + 150)  # the rules paid a jackpot's 150 balls into a cup of 10
	cup.pour(150)
	assert_eq(cup.pouring(), 20, "a big payout pours a capped stream of drops")
	assert_eq(cup.count(), 10, "the count waits for the balls to land")
	var seen := PackedInt32Array()
	for i in 240:
		cup._process(1.0 / 60.0)
		seen.append(cup.count())
	assert_eq(cup.pouring(), 0, "every drop landed")
	assert_eq(cup.count(), 160, "the whole payout reached the cup")
	assert_gt(
		Array(seen).filter(func(n: int) -> bool: return n > 10 and n < 160).size(),
		5,
		"it rose as they landed"
	)


func test_balls_have_a_dark_rim() -> void:
	var image := BallLayer.make_ball_image(64)
	var rim := image.get_pixel(32, 4)  # just inside the top edge
	var middle := image.get_pixel(32, 32)
	assert_lt(rim.get_luminance(), middle.get_luminance() * 0.5, "the outline is dark")
	assert_gt(BallLayer.DRAW_SCALE, 1.0, "drawn a little larger than the physics")
