extends GutTest
## Tulips on the shipped boards are real geometry: each tulip's wings are a world gate of
## two petals that swing open after a catch and shut after the next, drawn where the
## physics has them; an open tulip catches more balls than a shut one; and a board with
## tulips plays the same for 1, 2 and 4 threads.

const TULIPS := "res://levels/pachinko/tulips.board"
const DT := 1.0 / 120.0


func _tulips() -> BoardLevel:
	return BoardLoader.load_board(TULIPS).level


## Drops `count` balls spread across `spec`'s mouth ± 3 widths (one at a time, from 50 px
## above) into `world` and returns how many the tulip caught.
func _catches(level: BoardLevel, world: BallWorld, index: int, count: int) -> int:
	var spec := level.bonus_pockets[index]
	var tag := BonusGeometry.pocket_id(level, index)
	var caught := [0]
	var on_catch := func(_id: int, pocket: int) -> void:
		if pocket == tag:
			caught[0] += 1
	world.ball_captured.connect(on_catch)
	for k in count:
		var x := spec.position.x + spec.width * 3.0 * (2.0 * k / (count - 1.0) - 1.0)
		var id := world.spawn_ball(Vector2(x, spec.position.y - 50.0), Vector2.ZERO, 5.0)
		for _s in 240:
			world.step(DT)
			if not world.has_ball(id):
				break
		world.remove_ball(id)
	world.ball_captured.disconnect(on_catch)
	return caught[0]


func test_each_tulip_is_a_gate_of_two_petals_at_its_mouth() -> void:
	var level := _tulips()
	var world := BoardWorldFactory.build(level)
	assert_eq(world.shapes.gate_count(), 4, "Tulip Garden's four tulips")
	var plan := BonusGeometry.petal_plan(level)
	assert_eq(plan.size(), 8)
	for p in plan.size():
		var petal: Dictionary = plan[p]
		assert_almost_eq(world.shapes.get_petal_angle(p), petal["shut"], 1e-12, "petal %d shut" % p)


func test_an_open_tulip_catches_more_than_a_shut_one() -> void:
	var level := _tulips()
	var shut_world := BoardWorldFactory.build(level)
	var shut := _catches(level, shut_world, 0, 25)
	var open_world := BoardWorldFactory.build(level)
	open_world.shapes.set_gate_open(BonusGeometry.tulip_gate(level, 0), true, true)
	var open := _catches(level, open_world, 0, 25)
	gut.p("tulip 1 caught %d of 25 shut, %d open" % [shut, open])
	assert_gt(open, shut, "the spread wings turn more balls in")


func test_the_wings_are_drawn_where_the_world_has_them() -> void:
	var level := _tulips()
	var rules := PachinkoRules.new(level, 1)
	rules.bonus.catch(0)
	for _s in 12:
		rules.step()
	var amount := rules.bonus.openness(0)
	assert_between(amount, 0.2, 0.8, "swinging open")
	for p in 2:
		var petal: Dictionary = BonusGeometry.petal_plan(level)[p]
		var hinge: Vector2 = petal["hinge"]
		var length: float = petal["length"]
		var drawn := BonusGeometry.petal_tip(petal, amount)
		var world_tip := hinge + Vector2.from_angle(rules.world.shapes.get_petal_angle(p)) * length
		assert_almost_eq(drawn.distance_to(world_tip), 0.0, 1e-6, "petal %d drawn in place" % p)


func _autoplay_hash(thread_count: int) -> int:
	var rules := PachinkoRules.new(_tulips(), 3)
	rules.world.threads = thread_count
	rules.handle.set_power(40)
	rules.start_game()
	for _frame in 600:
		rules.handle.grip()
		rules.advance(1.0 / 60.0)
	assert_gt(rules.bonus.tulip_opens, 0, "a tulip opened")
	return rules.world.state_hash()


func test_a_tulip_board_plays_the_same_for_1_2_and_4_threads() -> void:
	var one := _autoplay_hash(1)
	assert_eq(_autoplay_hash(2), one, "2 threads")
	assert_eq(_autoplay_hash(4), one, "4 threads")
