extends GutTest
## The aim preview is the game's own flight, not a guess: a trial's players could not tell
## what power does, so while they aim the board shows where a shot of that power flies from
## the rail's mouth to its first pin. Each preview is checked against a ball the rules fire.


func _classic() -> BoardLevel:
	return BoardLoader.load_board("res://levels/pachinko/classic.board").level


# Where a ball the rules fire at `power` first meets a pin (its centre then).
func _fired_landing(level: BoardLevel, power: float) -> Vector2:
	var rules := PachinkoRules.new(level, 1)
	rules.start_game()
	var id := rules.fire(power)
	var met: Array[int] = []
	rules.world.pin_hit.connect(func(ball: int, _pin: int, _speed: float) -> void: met.append(ball))
	for i in int(LaunchPreview.MAX_SECONDS / rules.step_seconds()):
		rules.step()
		if met.has(id):
			return rules.world.get_ball_position(id)
	return Vector2.INF


func test_each_preview_lands_where_a_fired_ball_meets_its_first_pin() -> void:
	var level := _classic()
	var preview := LaunchPreview.measure(level)
	for power: float in [5.0, 30.0, 55.0, 80.0, 100.0]:
		var fired := _fired_landing(level, power)
		assert_almost_eq(preview.landing(power), fired, Vector2.ONE, "power %s" % power)


func test_a_preview_starts_at_the_rail_mouth_and_power_aims_it() -> void:
	var level := _classic()
	var preview := LaunchPreview.measure(level)
	var path := preview.path(40.0)
	assert_gt(path.size(), 3, "a flight, not a point")
	assert_eq(path[0], LaunchRail.entry_point(level), "every shot leaves the rail there")
	assert_gt(
		preview.landing(2.0).x, preview.landing(95.0).x + 200.0, "weak lands right, strong far left"
	)
