extends GutTest
## The game is not tied to the classic board: a smaller ring, another rail and one pocket
## paying 10 play by the same rules, and the launcher recalibrates to the new rail.


func _small_board() -> BoardLevel:
	var level := BoardLevel.new()
	level.kind = BoardLevel.Kind.PACHINKO
	level.board_id = "test_small"
	level.display_name = "Small"
	level.size = Vector2(520, 520)
	level.ball_radius = 5.0
	level.tuning = TuningPresets.pachinko()
	level.ring_center = Vector2(260, 260)
	level.ring_radius = 240.0
	level.rail_width = 20.0
	level.rail_start_deg = 45.0
	level.rail_end_deg = -110.0
	level.gutter_start_deg = 55.0
	level.gutter_end_deg = 125.0
	level.gutter_bounces = 4
	level.pin_radius = 1.5
	level.cup_start_balls = 10
	level.pockets = [PocketSpec.create(Vector2(260, 300), 22.0, 24.0, 10)]
	var lattice := PinPatterns.staggered_lattice(Rect2(60, 80, 400, 330), Vector2(28, 26))
	lattice = PinPatterns.inside_circle(lattice, level.ring_center, 200.0)
	lattice = PinPatterns.away_from(lattice, [Vector2(260, 300)] as PackedVector2Array, 30.0)
	level.pins = lattice
	var owners := PackedInt32Array()
	owners.resize(lattice.size())
	owners.fill(-1)
	level.pin_pocket = owners
	var special := PackedByteArray()
	special.resize(lattice.size())
	level.pin_special = special
	PocketStamp.apply(level, 0)
	return level


func test_every_power_clears_another_rail() -> void:
	var level := _small_board()
	for p in [0.01, 1.0, 50.0, 100.0]:
		var rules := PachinkoRules.new(level, 3)
		rules.start_game()
		var id := rules.fire(p)
		var inside := LaunchRail.guide_radius(level) - level.ball_radius - 3.0
		var entered := false
		for i in int(5.0 / rules.step_seconds()):
			rules.step()
			if not rules.world.has_ball(id):
				break
			if rules.world.get_ball_position(id).distance_to(level.ring_center) < inside:
				entered = true
				break
		assert_true(entered, "power %s clears this rail" % p)
		assert_eq(rules.ledger.returned, 0)
		assert_true(rules.accounting_ok())


func test_autoplay_on_another_board_keeps_every_ball() -> void:
	var result := PachinkoAutoplay.run(_small_board(), 20.0, 5)
	assert_true(result["accounting_ok"])
	assert_eq((result["pocket_hits"] as Array).size(), 1)
	assert_eq(int(result["payouts"]), int(result["pocket_hits"][0]) * 10, "this pocket pays 10")
	assert_gt(int(result["shots"]), 10)
