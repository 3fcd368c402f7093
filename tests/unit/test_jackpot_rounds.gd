extends GutTest
## A jackpot's numbered rounds: a jackpot opens the attacker for round 1 of
## JackpotRounds.ROUNDS, each round ends after the attacker's catches or its seconds, the next
## opens after a short break, no spin starts until the last round is over, and the jackpot
## reports what it paid. The reach is signalled for the view and the music.

const CLASSIC := "res://levels/pachinko/classic.board"
const ATTACKER := 1
const OPEN_SECONDS := 5.0
const OPEN_CATCHES := 3
const PAYOUT := 12


# The classic ring with no field pins or pockets, a start pocket and an attacker.
func _board() -> BoardLevel:
	var level: BoardLevel = (load(CLASSIC) as BoardLevel).duplicate_level()
	level.pins = PackedVector2Array()
	level.pin_pocket = PackedInt32Array()
	level.pin_special = PackedByteArray()
	level.pockets = []
	var start := BonusPocketSpec.of_role(
		BonusPocketSpec.Role.START, Vector2(250, 300), 24.0, 26.0, 3
	)
	start.symbols = 2
	var attacker := BonusPocketSpec.of_role(
		BonusPocketSpec.Role.ATTACKER, Vector2(350, 420), 60.0, 32.0, PAYOUT
	)
	attacker.open_seconds = OPEN_SECONDS
	attacker.open_catches = OPEN_CATCHES
	level.bonus_pockets = [start, attacker]
	return level


func _machine() -> BonusMachine:
	var level := _board()
	return BonusMachine.new(level, BoardWorldFactory.build(level), 1)


func _jackpot(machine: BonusMachine) -> void:
	machine._on_spin_finished(PackedInt32Array([1, 1, 1]), true)


func test_rounds_count_from_one_to_the_last_and_then_the_jackpot_is_over() -> void:
	var rounds := JackpotRounds.new()
	var started: Array[int] = []
	var paid: Array[int] = []
	rounds.round_started.connect(func(n: int, _of: int) -> void: started.append(n))
	rounds.finished.connect(func(balls: int) -> void: paid.append(balls))
	assert_false(rounds.active())
	rounds.begin()
	assert_eq(rounds.current_round, 1)
	for n in JackpotRounds.ROUNDS:
		rounds.add_paid(10)
		rounds.end_round()
		rounds.end_round()  # a second report of the same round's end counts once
		rounds.advance(JackpotRounds.BREAK_SECONDS * 0.5)
		rounds.advance(JackpotRounds.BREAK_SECONDS * 0.5 + 0.01)
	var expected: Array[int] = []
	for n in JackpotRounds.ROUNDS:
		expected.append(n + 1)
	assert_eq(started, expected, "rounds 1 to %d, each once" % JackpotRounds.ROUNDS)
	assert_false(rounds.active(), "over after the last round")
	assert_eq(paid, [10 * JackpotRounds.ROUNDS], "the jackpot reports all it paid")


func test_a_break_separates_the_rounds() -> void:
	var rounds := JackpotRounds.new()
	rounds.begin()
	rounds.end_round()
	assert_true(rounds.in_break())
	rounds.advance(JackpotRounds.BREAK_SECONDS - 0.1)
	assert_eq(rounds.current_round, 1, "still in the break")
	rounds.advance(0.2)
	assert_eq(rounds.current_round, 2)
	assert_false(rounds.in_break())


func test_a_round_ends_after_the_attackers_catches() -> void:
	var machine := _machine()
	var ended: Array[int] = []
	machine.jackpot_round_ended.connect(func(n: int, _of: int) -> void: ended.append(n))
	_jackpot(machine)
	assert_true(machine.is_open(ATTACKER), "round 1 opens the attacker")
	for i in OPEN_CATCHES - 1:
		machine.catch(ATTACKER)
	assert_true(machine.is_open(ATTACKER))
	assert_eq(ended, [], "a ball short of the round's catches")
	machine.catch(ATTACKER)
	assert_false(machine.is_open(ATTACKER), "shut after %d balls in" % OPEN_CATCHES)
	assert_eq(ended, [1])
	machine.advance(JackpotRounds.BREAK_SECONDS + 0.01)
	assert_true(machine.is_open(ATTACKER), "round 2 opens it again")
	assert_eq(machine.rounds.current_round, 2)


func test_a_round_ends_after_the_attackers_seconds() -> void:
	var machine := _machine()
	var ended: Array[int] = []
	machine.jackpot_round_ended.connect(func(n: int, _of: int) -> void: ended.append(n))
	_jackpot(machine)
	machine.catch(ATTACKER)
	machine.advance(OPEN_SECONDS - 0.1)
	assert_true(machine.is_open(ATTACKER))
	machine.advance(0.2)
	assert_false(machine.is_open(ATTACKER), "shut after %s seconds" % OPEN_SECONDS)
	assert_eq(ended, [1])


func test_a_whole_jackpot_pays_its_rounds_and_no_spin_starts_meanwhile() -> void:
	var machine := _machine()
	var paid: Array[int] = []
	machine.jackpot_ended.connect(func(balls: int) -> void: paid.append(balls))
	_jackpot(machine)
	machine.catch(0)  # a spin waits for the jackpot to end
	for n in JackpotRounds.ROUNDS:
		assert_eq(machine.rounds.current_round, n + 1)
		for i in OPEN_CATCHES:
			machine.catch(ATTACKER)
		machine.advance(0.5)
		if n < JackpotRounds.ROUNDS - 1:
			assert_eq(machine.reel_spins, 0, "no spin in round %d or its break" % (n + 1))
		machine.advance(JackpotRounds.BREAK_SECONDS)
	assert_false(machine.rounds.active())
	assert_eq(paid, [JackpotRounds.ROUNDS * OPEN_CATCHES * PAYOUT])
	assert_eq(machine.counters()["jackpot_paid"], JackpotRounds.ROUNDS * OPEN_CATCHES * PAYOUT)
	assert_eq(machine.jackpots_finished, 1)
	machine.advance(0.1)
	assert_eq(machine.reel_spins, 1, "the waiting spin starts once the jackpot is over")


func test_a_reach_is_signalled_when_the_second_reel_matches_and_ends_with_the_last() -> void:
	var machine := _machine()
	var heard: Array[String] = []
	machine.reach_started.connect(func() -> void: heard.append("reach"))
	machine.reach_ended.connect(func(won: bool) -> void: heard.append("end %s" % won))
	machine.reels.start(PackedInt32Array([1, 1, 0]), 2)
	for frame in 60 * 6:
		machine.reels.advance(1.0 / 60.0)
		if machine.reels.in_reach():
			assert_between(machine.reels.reach_progress(), 0.0, 1.0)
	assert_eq(heard, ["reach", "end false"])
	heard.clear()
	machine.reels.start(PackedInt32Array([0, 1, 1]), 2)
	for frame in 60 * 6:
		machine.reels.advance(1.0 / 60.0)
	assert_eq(heard, [], "no reach when the first two differ")


func test_the_last_reel_of_a_reach_slows_down() -> void:
	var reels := ReelSet.new()
	reels.start(PackedInt32Array([2, 2, 1]), 5)
	var last := ReelSet.REELS - 1
	var begin := reels.stop_time(last - 1)
	var end := reels.stop_time(last)
	assert_almost_eq(end - begin, ReelSet.STOP_SECONDS[last] - begin + ReelSet.REACH_EXTRA, 1e-9)
	reels.elapsed = begin + 0.05
	var early := reels.roll_position(last)
	reels.elapsed = begin + 0.15
	var early_rate := (reels.roll_position(last) - early) / 0.1
	reels.elapsed = end - 0.15
	var late := reels.roll_position(last)
	reels.elapsed = end - 0.05
	var late_rate := (reels.roll_position(last) - late) / 0.1
	assert_lt(late_rate, early_rate * 0.5, "slower at the end of the reach")
