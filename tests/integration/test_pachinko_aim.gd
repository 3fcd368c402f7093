extends GutTest
## Power aims across the whole field: on the shipped boards the weakest fifth of power
## meets its first pin within a fifth of the ring's width from the rail side, and the
## strongest fifth within a third of the width from the far side (the mouth speed, which
## power sets, is what moves it).

const BOARDS := ["classic", "tulips", "windmills"]
## The boards the aim rule is held to: every shipped one.
const AIMED_BOARDS := ["classic", "tulips", "windmills", "fever", "hanami"]


func _board(id: String) -> BoardLevel:
	var loaded := BoardLoader.load_board("res://levels/pachinko/%s.board" % id)
	assert_not_null(loaded.level, "%s loads" % id)
	return loaded.level


func _mean_entry_x(level: BoardLevel, powers: Array) -> float:
	var sum := 0.0
	for power: float in powers:
		var shot := PowerAim.shoot(level, power)
		assert_false(is_nan(shot["entry_x"]), "power %s reached a pin" % power)
		sum += shot["entry_x"]
	return sum / powers.size()


func _median_entry_x(level: BoardLevel, powers: Array) -> float:
	var xs: Array[float] = []
	for power: float in powers:
		var shot := PowerAim.shoot(level, power)
		assert_false(is_nan(shot["entry_x"]), "power %s reached a pin" % power)
		xs.append(shot["entry_x"])
	xs.sort()
	return xs[xs.size() / 2]


func test_weak_fifth_drops_beside_the_rail_and_strong_fifth_reaches_the_far_side() -> void:
	for id: String in AIMED_BOARDS:
		var level := _board(id)
		var width := level.ring_radius * 2.0
		var rail_side := level.ring_center.x + level.ring_radius - width * 0.2
		var far_side := level.ring_center.x - level.ring_radius + width / 3.0
		var weak := _median_entry_x(level, [1.0, 5.0, 9.0, 13.0, 17.0])
		var strong := _median_entry_x(level, [83.0, 87.0, 91.0, 95.0, 99.0])
		assert_gte(weak, rail_side, "%s: the weak fifth meets the pins at x %d" % [id, weak])
		assert_lte(strong, far_side, "%s: the strong fifth meets the pins at x %d" % [id, strong])


func test_strong_shots_carry_across_the_top_and_weak_ones_drop_near_the_rail() -> void:
	for id: String in BOARDS:
		var level := _board(id)
		var weak := _mean_entry_x(level, [2.0, 6.0, 10.0])
		var strong := _mean_entry_x(level, [92.0, 96.0, 100.0])
		assert_gt(
			weak - strong, 60.0, "%s: weak enters at x %d, strong at x %d" % [id, weak, strong]
		)
		var exit := LaunchRail.entry_point(level)
		assert_gt(exit.x, level.ring_center.x, "%s: the rail opens right of the top" % id)


func test_the_flight_lane_has_no_free_pin() -> void:
	for id: String in BOARDS:
		var level := _board(id)
		var in_lane := 0
		for i in level.pins.size():
			if level.pin_pocket[i] < 0 and LaunchRail.in_flight_lane(level, level.pins[i]):
				in_lane += 1
		assert_eq(in_lane, 0, "%s: no pin in the way of a shot's flight" % id)


func test_total_variation_is_zero_for_equal_and_one_for_disjoint_shares() -> void:
	assert_eq(PowerAim.tv_distance({"p0": 0.5, "p1": 0.5}, {"p1": 0.5, "p0": 0.5}), 0.0)
	assert_eq(PowerAim.tv_distance({"p0": 1.0}, {"p1": 1.0}), 1.0)
	assert_almost_eq(
		PowerAim.tv_distance({"p0": 0.75, "p1": 0.25}, {"p0": 0.25, "p1": 0.75}), 0.5, 1e-6
	)
