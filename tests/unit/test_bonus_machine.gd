extends GutTest
## The bonus layer in the world and in the rules: bonus cups catch, an attacker's closed lid
## deflects a falling ball and an open one lets it in, tulips open after a catch and close
## after the next, the reels stop one by one and a jackpot opens the attacker, and the same
## seed gives the same reel results.

const CLASSIC := "res://levels/pachinko/classic.board"
const DT := 1.0 / 120.0
const START := Vector2(250, 300)
const ATTACKER := Vector2(350, 420)
const TULIP := Vector2(450, 300)


# The classic ring and rail with no field pins or pockets, plus one of each bonus pocket.
func _bonus_board() -> BoardLevel:
	var level: BoardLevel = (load(CLASSIC) as BoardLevel).duplicate_level()
	level.pins = PackedVector2Array()
	level.pin_pocket = PackedInt32Array()
	level.pin_special = PackedByteArray()
	level.pockets = []
	var start := BonusPocketSpec.of_role(BonusPocketSpec.Role.START, START, 24.0, 26.0, 3)
	start.symbols = 2
	var attacker := BonusPocketSpec.of_role(BonusPocketSpec.Role.ATTACKER, ATTACKER, 60.0, 32.0, 15)
	attacker.open_seconds = 5.0
	attacker.open_catches = 2
	var tulip := BonusPocketSpec.of_role(BonusPocketSpec.Role.TULIP, TULIP, 24.0, 26.0, 5)
	level.bonus_pockets = [start, attacker, tulip]
	return level


# Drops a ball from just above `mouth` into `world`; the pocket id it was caught by, or -1.
func _drop(world: BallWorld, mouth: Vector2, seconds := 3.0) -> int:
	var caught := [-1]
	var on_pocket := func(_id: int, pocket: int) -> void: caught[0] = pocket
	world.ball_captured.connect(on_pocket)
	var id := world.spawn_ball(mouth + Vector2(0.5, -40.0), Vector2.ZERO, 5.0)
	for step in int(seconds / DT):
		world.step(DT)
		if not world.has_ball(id):
			break
	world.ball_captured.disconnect(on_pocket)
	world.remove_ball(id)
	return caught[0]


func test_the_factory_adds_bonus_cups_after_the_pins_and_parts_first() -> void:
	var level := _bonus_board()
	var world := BoardWorldFactory.build(level)
	var plan := BonusGeometry.wall_plan(level)
	assert_eq(plan.size(), 2, "a lid of two halves")
	assert_true(
		world.shapes.is_wall_enabled(0) and world.shapes.is_wall_enabled(1), "the lid starts closed"
	)
	assert_eq(world.shapes.gate_count(), 1, "the tulip's wings are one gate")
	assert_eq(world.shapes.get_gate_openness(0), 0.0, "shut")
	assert_almost_eq(
		world.shapes.get_petal_angle(0), -PI / 2.0, 1e-12, "a shut wing stands upright"
	)
	var pins := 0
	for spec in level.bonus_pockets:
		pins += BonusGeometry.rim_pins(level, spec).size()
	assert_eq(world.shapes.pin_count(), pins)


func test_a_start_pocket_catches_a_falling_ball() -> void:
	var level := _bonus_board()
	var world := BoardWorldFactory.build(level)
	assert_eq(_drop(world, START), BonusGeometry.pocket_id(level, 0))


func test_a_closed_attacker_deflects_and_an_open_one_catches() -> void:
	var level := _bonus_board()
	var world := BoardWorldFactory.build(level)
	assert_eq(_drop(world, ATTACKER, 2.0), -1, "the closed lid turned the ball away")
	var machine := BonusMachine.new(level, world, 1)
	machine._on_spin_finished(PackedInt32Array([1, 1, 1]), true)
	assert_true(machine.is_open(1))
	assert_false(world.shapes.is_wall_enabled(0), "the lid is up")
	assert_eq(_drop(world, ATTACKER), BonusGeometry.pocket_id(level, 1))


func test_an_attacker_closes_after_its_catches_or_its_time() -> void:
	var level := _bonus_board()
	var world := BoardWorldFactory.build(level)
	var machine := BonusMachine.new(level, world, 1)
	machine._on_spin_finished(PackedInt32Array([0, 0, 0]), true)
	assert_eq(machine.catch(1), 15)
	assert_true(machine.is_open(1), "one catch of two")
	assert_eq(machine.catch(1), 15)
	assert_false(machine.is_open(1), "closed after its second catch")
	assert_true(world.shapes.is_wall_enabled(0), "the lid is back")
	assert_eq(machine.attacker_paid, 30)
	machine.advance(JackpotRounds.BREAK_SECONDS + 0.01)
	assert_true(machine.is_open(1), "the next round opens it again")
	machine.advance(4.9)
	assert_true(machine.is_open(1))
	machine.advance(0.2)
	assert_false(machine.is_open(1), "closed after five seconds")
	assert_eq(machine.jackpots, 1)


func test_a_tulip_opens_after_a_catch_and_closes_after_the_next() -> void:
	var level := _bonus_board()
	var world := BoardWorldFactory.build(level)
	var machine := BonusMachine.new(level, world, 1)
	assert_eq(machine.catch(2), 5)
	assert_true(machine.is_open(2))
	assert_true(world.shapes.is_gate_opening(0), "the wings swing open")
	for _i in 12:
		world.step(DT)
	assert_between(machine.openness(2), 0.4, 0.6, "half way after half the swing")
	for _i in 12:
		world.step(DT)
	assert_eq(machine.openness(2), 1.0, "spread after the whole swing")
	machine.catch(2)
	assert_false(machine.is_open(2))
	assert_false(world.shapes.is_gate_opening(0), "the wings swing shut")
	for _i in 24:
		world.step(DT)
	assert_eq(machine.openness(2), 0.0)
	assert_eq(machine.tulip_opens, 1)


func test_an_open_tulip_catches_a_ball_a_closed_one_misses() -> void:
	var level := _bonus_board()
	var world := BoardWorldFactory.build(level)
	var machine := BonusMachine.new(level, world, 1)
	var beside := TULIP + Vector2(22.0, 0.0)
	assert_eq(_drop(world, beside), -1, "closed: a ball beside the mouth falls past")
	machine.catch(2)
	for _i in 30:
		world.step(DT)
	assert_eq(_drop(world, beside), BonusGeometry.pocket_id(level, 2), "open: the wing turns it in")


func test_reels_stop_one_by_one_and_a_jackpot_opens_the_attacker() -> void:
	var level := _bonus_board()
	var machine := BonusMachine.new(level, BoardWorldFactory.build(level), 7)
	var stops: Array[int] = []
	machine.reel_stopped.connect(func(reel: int, _symbol: int) -> void: stops.append(reel))
	for i in 3:
		machine.catch(0)
	assert_eq(machine.queued_spins(), 3)
	var opened := false
	for frame in 60 * 30:
		machine.advance(1.0 / 60.0)
		opened = opened or machine.any_attacker_open()
	assert_eq(machine.reel_spins, 3)
	assert_eq(stops.slice(0, 3), [0, 1, 2], "left to right")
	assert_eq(machine.queued_spins(), 0)
	assert_eq(opened, machine.jackpots > 0, "the attacker opened exactly when a jackpot came")


func test_the_same_seed_gives_the_same_reels() -> void:
	var results: Array = []
	for run in 3:
		var level := _bonus_board()
		var machine := BonusMachine.new(level, BoardWorldFactory.build(level), 99 if run < 2 else 5)
		var seen := PackedInt32Array()
		machine.reel_stopped.connect(func(_reel: int, symbol: int) -> void: seen.append(symbol))
		for spin in 4:
			machine.catch(0)
			for frame in 60 * 4:
				machine.advance(1.0 / 60.0)
		results.append(seen)
	assert_eq(results[0], results[1])
	assert_eq(results[0].size(), 12)


func test_the_queue_holds_at_most_four_spins() -> void:
	var level := _bonus_board()
	var machine := BonusMachine.new(level, BoardWorldFactory.build(level), 1)
	for i in 9:
		assert_eq(machine.catch(0), 3, "a start pocket pays every catch")
	assert_eq(machine.queued_spins(), BonusMachine.MAX_QUEUED)


func test_rules_pay_bonus_catches_and_report_the_counters() -> void:
	var level := _bonus_board()
	var rules := PachinkoRules.new(level, 3)
	rules.start_game()
	var id := rules.fire(60.0)
	assert_gt(id, -1)
	# Put the fired ball over the start pocket and let it drop in.
	rules.world.set_ball_position(id, START + Vector2(0.5, -40.0))
	rules.world.set_ball_velocity(id, Vector2.ZERO)
	var cup_before := rules.cup
	for frame in 240:
		rules.advance(1.0 / 60.0)
	assert_eq(rules.cup, cup_before + 3, "the start pocket paid three balls")
	var stats := rules.stats()
	assert_eq(stats["reel_spins"], 1)
	assert_true(stats.has("jackpots") and stats.has("attacker_paid") and stats.has("tulip_opens"))
	assert_true(rules.accounting_ok())


func test_world_pockets_list_bonus_cups_after_the_levels_pockets() -> void:
	var level := _bonus_board()
	level.pockets = [PocketSpec.create(Vector2(350, 600), 22.0, 24.0, 4)]
	var facts := BonusGeometry.world_pockets(level)
	assert_eq(facts.size(), 4)
	assert_eq(facts[0]["role"], "pocket")
	assert_eq(facts[1]["role"], "start_pocket")
	assert_eq(facts[1]["payout"], 3)
	assert_eq(facts[3]["position"], TULIP)
	assert_eq(BonusGeometry.bonus_index(level, 1), 0, "world pocket 1 is bonus pocket 0")
	assert_eq(BonusGeometry.lowest_catch_y(level), ATTACKER.y + 32.0)


func test_rules_with_a_bonus_layer_are_freed_when_dropped() -> void:
	# A reference cycle (machine -> reels -> a connection holding the machine) once kept
	# every game's rules, world and bonus machine alive until exit.
	var rules := PachinkoRules.new(_bonus_board(), 3)
	var machine_ref: WeakRef = weakref(rules.bonus)
	var world_ref: WeakRef = weakref(rules.world)
	rules = null
	assert_null(machine_ref.get_ref(), "the bonus machine is freed with its rules")
	assert_null(world_ref.get_ref(), "and so is the world")


func test_the_fever_state_shows_while_the_attacker_is_open() -> void:
	var level := _bonus_board()
	var world := BoardWorldFactory.build(level)
	var machine := BonusMachine.new(level, world, 1)
	var glow := FeverGlow.new()
	add_child_autofree(glow)
	glow.bind(level, machine)
	assert_false(glow.is_lit(), "no fever before a jackpot")
	assert_eq(glow.caption(), "")
	machine._on_spin_finished(PackedInt32Array([1, 1, 1]), true)
	assert_true(glow.is_lit(), "a jackpot opens the attacker: fever")
	assert_eq(glow.caption(), "ROUND 1 / %d  5s  2 to catch" % JackpotRounds.ROUNDS)
	machine.advance(5.5)
	assert_true(glow.is_lit(), "a break between rounds is still the jackpot")
	assert_eq(glow.caption(), "ROUND 1 / %d  next round…" % JackpotRounds.ROUNDS)
	for n in JackpotRounds.ROUNDS:
		machine.advance(JackpotRounds.BREAK_SECONDS + 0.01)
		machine.advance(5.5)
	assert_false(glow.is_lit(), "the last round is over")
