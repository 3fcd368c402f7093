class_name BonusMachine
extends RefCounted
## The bonus layer of a pachinko machine, without pictures: start pockets spin the reels,
## a jackpot (three equal symbols) opens the attackers' lids for JackpotRounds.ROUNDS
## numbered rounds (each over after the attacker's catches or seconds), and tulips open
## after a catch and close after the next. It owns no balls: PachinkoRules tells it about
## catches (`catch`) and time (`advance`), and it switches the lids and swings the tulips'
## wings (the world's gates) in the world.
## Reel results come from a generator seeded from the game's seed, so the same seed and
## the same shots give the same spins, jackpots and payouts.

## A start pocket caught a ball; `queued` spins are waiting (the one under way excluded).
signal start_caught(index: int, queued: int)
## The reels began a spin with `symbols` symbols per reel.
signal reels_started(symbols: int)
## One reel stopped on `symbol`.
signal reel_stopped(reel: int, symbol: int)
## Every reel stopped; `jackpot` when they match.
signal reels_finished(result: PackedInt32Array, jackpot: bool)
## Attacker `index` opened (after a jackpot) or closed (time or catches used up).
signal attacker_changed(index: int, open: bool)
## Tulip `index` opened or closed.
signal tulip_changed(index: int, open: bool)
## The first two reels stopped on the same symbol: the last one decides a jackpot.
signal reach_started
## The last reel of a reach stopped; `jackpot` when it matched.
signal reach_ended(jackpot: bool)
## Round `round` of `rounds` of a jackpot began (the attackers open).
signal jackpot_round_started(round: int, rounds: int)
## Round `round` of `rounds` of a jackpot ended (the attackers shut).
signal jackpot_round_ended(round: int, rounds: int)
## A jackpot's last round ended; it paid `paid` balls.
signal jackpot_ended(paid: int)
## A jackpot came back to back with the last: announced first, its round 1 opens after
## JackpotRounds.AGAIN_SECONDS.
signal jackpot_again
## The spin the house gave (grant_house_jackpot) ended on its jackpot.
signal house_jackpot_landed
## The next spin was made the house's jackpot (grant_house_jackpot): a replay records it.
signal house_jackpot_granted

## Spins a start pocket can hold while the reels are busy (real machines show four lamps).
const MAX_QUEUED := 4
## A Gold spin (the gold pins' prize, grant_gold_spin) is always a reach, and its last reel
## matches with this chance.
const GOLD_JACKPOT_ODDS := 1.0 / 3.0

## Spins started.
var reel_spins := 0
## Spins that ended on three equal symbols.
var jackpots := 0
## Balls the attackers paid.
var attacker_paid := 0
## Balls the attackers paid during jackpots (a jackpot's payout, summed).
var jackpot_paid := 0
## Jackpots whose last round has ended.
var jackpots_finished := 0
## The rounds of the jackpot under way (read by the view).
var rounds := JackpotRounds.new()
## Times a tulip opened.
var tulip_opens := 0
## The reels (read by the view).
var reels := ReelSet.new()
## False while the player has no ball on the board and is not shooting: an open attacker's
## seconds wait (the rules set it each step). A real machine's round runs on time, but a
## player reading the screen must not lose one (trial 7).
var round_clock_runs := true

var _level: BoardLevel
var _world: BallWorld
var _rng := RandomNumberGenerator.new()
## The next spin lands a jackpot (grant_house_jackpot), drawn as a reach like any other.
var _house_next := false
## The last spin finished was the house's.
var _house_last := false
## Symbol counts of the spins waiting, oldest first.
var _queued := PackedInt32Array()
## Per waiting spin: 1 for a Gold spin.
var _queued_gold := PackedByteArray()
## Per bonus pocket: 1 while open (attacker lid up, tulip wings spread).
var _open := PackedByteArray()
## Per attacker: seconds and catches left in its open round.
var _time_left := PackedFloat64Array()
var _catches_left := PackedInt32Array()
## World wall index → [bonus pocket index, BonusGeometry.Part].
var _walls: Array[Dictionary] = []
## Per bonus pocket: its world gate (a tulip's wings), or -1.
var _gates := PackedInt32Array()


## The bonus layer of `level` over `world` (built by BoardWorldFactory, which put the lids
## first among its walls and made the tulips' wings its gates). `rng_seed` fixes the reel
## results.
func _init(level: BoardLevel, world: BallWorld, rng_seed: int) -> void:
	_level = level
	_world = world
	_rng.seed = hash([rng_seed, "reels"])
	var count := level.bonus_pockets.size() if level != null else 0
	_open.resize(count)
	_time_left.resize(count)
	_catches_left.resize(count)
	_gates.resize(count)
	_gates.fill(-1)
	if level != null and world != null:
		_walls = BonusGeometry.wall_plan(level)
		if _walls.size() > world.shapes.wall_count():
			push_error("BonusMachine: the world lacks the bonus walls; lids will not move")
			_walls.clear()
		for i in count:
			var gate := BonusGeometry.tulip_gate(level, i)
			if gate >= world.shapes.gate_count():
				push_error("BonusMachine: the world lacks the tulips' gates; wings will not move")
				gate = -1
			_gates[i] = gate
	# Methods, not a lambda: a lambda would hold this machine, which holds the reels that
	# hold the lambda, and the cycle would keep the machine and its world alive forever.
	reels.reel_stopped.connect(_on_reel_stopped)
	reels.spin_finished.connect(_on_spin_finished)
	rounds.round_started.connect(_on_round_started)
	rounds.round_ended.connect(_on_round_ended)
	rounds.finished.connect(_on_jackpot_finished)
	rounds.again_announced.connect(_on_jackpot_again)


## True when the board has any bonus pocket.
func has_bonus() -> bool:
	return not _open.is_empty()


## A ball reached the catching pin of bonus pocket `index`: returns the balls it pays.
func catch(index: int) -> int:
	if index < 0 or index >= _open.size():
		return 0
	var spec := _level.bonus_pockets[index]
	match spec.role:
		BonusPocketSpec.Role.START:
			if _queued.size() < MAX_QUEUED:
				_queued.append(spec.symbols)
				_queued_gold.append(0)
			start_caught.emit(index, _queued.size())
		BonusPocketSpec.Role.ATTACKER:
			attacker_paid += maxi(spec.payout, 0)
			if rounds.active():
				jackpot_paid += maxi(spec.payout, 0)
				rounds.add_paid(spec.payout)
			if is_open(index):
				_catches_left[index] -= 1
				if _catches_left[index] <= 0:
					_set_open(index, false)
					_end_round_when_shut()
		BonusPocketSpec.Role.TULIP:
			_set_open(index, not is_open(index))
			if is_open(index):
				tulip_opens += 1
	return maxi(spec.payout, 0)


## Runs the timers for `delta` seconds of game time: open attackers count down, a jackpot's
## break between rounds runs, the reels turn, and a waiting spin starts once the reels are
## free and no jackpot is on.
func advance(delta: float) -> void:
	if _open.is_empty() or delta <= 0.0:
		return
	# A break that begins in this call starts counting in the next, and a round it opens
	# is not charged for this one.
	var was_in_break := rounds.in_break()
	for i in _open.size():
		if _open[i] != 0 and _is_attacker(i) and round_clock_runs:
			_time_left[i] -= delta
			if _time_left[i] <= 0.0:
				_set_open(i, false)
				_end_round_when_shut()
	if was_in_break:
		rounds.advance(delta)
	else:
		rounds.count_time(delta)
	if reels.busy():
		reels.advance(delta)
	elif not _queued.is_empty() and not rounds.active():
		_start_spin()


## Makes the next spin a jackpot: a new player's first start-pocket hit on a reel machine
## (HouseJackpot decides when; the analysis and the autoplay never ask for one, so their
## figures leave it out). A replay records it (ReplayRecorder) and asks again.
func grant_house_jackpot() -> void:
	_house_next = true
	house_jackpot_granted.emit()


## Queues a Gold spin (the gold pins' prize on a reel machine): a reach for sure, a jackpot
## at GOLD_JACKPOT_ODDS, drawn from the reels' own generator. Returns false on a board
## without reels.
func grant_gold_spin() -> bool:
	for spec in _level.bonus_pockets:
		if spec.role == BonusPocketSpec.Role.START:
			_queued.append(spec.symbols)
			_queued_gold.append(1)
			return true
	return false


## True when the board has reels (a start pocket spins them).
func has_reels() -> bool:
	for spec in _level.bonus_pockets:
		if spec.role == BonusPocketSpec.Role.START:
			return true
	return false


## True while the next spin is the house's jackpot.
func has_house_jackpot() -> bool:
	return _house_next


## True when the spin that finished last was the house's jackpot.
func last_spin_was_house() -> bool:
	return _house_last


## True while bonus pocket `index` is open.
func is_open(index: int) -> bool:
	return index >= 0 and index < _open.size() and _open[index] != 0


## How open bonus pocket `index` is as the world has it (0 shut .. 1 open): a tulip's wings
## swing between the two, a lid is one or the other.
func openness(index: int) -> float:
	if index >= 0 and index < _gates.size() and _gates[index] >= 0:
		return _world.shapes.get_gate_openness(_gates[index])
	return 1.0 if is_open(index) else 0.0


## True while any attacker's lid is up (a jackpot round).
func any_attacker_open() -> bool:
	for i in _open.size():
		if _open[i] != 0 and _is_attacker(i):
			return true
	return false


## Seconds left in attacker `index`'s open round (0 when closed).
func time_left(index: int) -> float:
	return _time_left[index] if is_open(index) else 0.0


## Catches left in attacker `index`'s open round (0 when closed).
func catches_left(index: int) -> int:
	return _catches_left[index] if is_open(index) else 0


## Spins waiting for the reels.
func queued_spins() -> int:
	return _queued.size()


## The counters the stats panel and the autoplay report.
func counters() -> Dictionary:
	return {
		"reel_spins": reel_spins,
		"jackpots": jackpots,
		"attacker_paid": attacker_paid,
		"jackpot_paid": jackpot_paid,
		"jackpots_finished": jackpots_finished,
		"tulip_opens": tulip_opens,
	}


func _start_spin() -> void:
	var symbol_count := maxi(_queued[0], 1)
	var gold := _queued_gold[0] != 0
	_queued.remove_at(0)
	_queued_gold.remove_at(0)
	var landing := PackedInt32Array()
	for reel in ReelSet.REELS:
		landing.append(_rng.randi_range(0, symbol_count - 1))
	if gold:
		_gold_landing(landing, symbol_count)
	_house_last = _house_next
	if _house_next:  # the house's jackpot: three of the first reel's symbol
		_house_next = false
		landing.fill(landing[0])
	reel_spins += 1
	reels.start(landing, symbol_count)
	reels_started.emit(symbol_count)


# A Gold spin: the second reel matches the first; the last one at GOLD_JACKPOT_ODDS, else
# any other symbol.
func _gold_landing(landing: PackedInt32Array, symbol_count: int) -> void:
	landing[1] = landing[0]
	if symbol_count < 2 or _rng.randf() < GOLD_JACKPOT_ODDS:
		landing[2] = landing[0]
	else:
		landing[2] = (landing[0] + _rng.randi_range(1, symbol_count - 1)) % symbol_count


func _on_reel_stopped(reel: int, symbol: int) -> void:
	reel_stopped.emit(reel, symbol)
	if reels.is_reach() and reel == ReelSet.REELS - 2:
		reach_started.emit()
	elif reels.is_reach() and reel == ReelSet.REELS - 1:
		reach_ended.emit(reels.is_jackpot())


func _on_spin_finished(result: PackedInt32Array, jackpot: bool) -> void:
	if jackpot:
		jackpots += 1
		if _has_attacker():
			rounds.begin()
	reels_finished.emit(result, jackpot)
	if _house_last and jackpot:
		house_jackpot_landed.emit()


func _on_round_started(round_number: int, count: int) -> void:
	for i in _open.size():
		if _is_attacker(i):
			var spec := _level.bonus_pockets[i]
			_time_left[i] = spec.open_seconds
			_catches_left[i] = maxi(spec.open_catches, 1)
			_set_open(i, true)
	jackpot_round_started.emit(round_number, count)


func _on_jackpot_again() -> void:
	jackpot_again.emit()


func _on_round_ended(round_number: int, count: int) -> void:
	jackpot_round_ended.emit(round_number, count)


func _on_jackpot_finished(paid: int) -> void:
	jackpots_finished += 1
	jackpot_ended.emit(paid)


# A round is over once every attacker has shut.
func _end_round_when_shut() -> void:
	if rounds.active() and not any_attacker_open():
		rounds.end_round()


func _has_attacker() -> bool:
	for i in _open.size():
		if _is_attacker(i):
			return true
	return false


func _is_attacker(index: int) -> bool:
	return _level.bonus_pockets[index].role == BonusPocketSpec.Role.ATTACKER


func _set_open(index: int, open: bool) -> void:
	if is_open(index) == open:
		return
	_open[index] = 1 if open else 0
	for wall in _walls.size():
		var entry: Dictionary = _walls[wall]
		if entry["item"] == index:
			var part: BonusGeometry.Part = entry["part"]
			_world.shapes.set_wall_enabled(wall, BonusGeometry.part_solid(part, open))
	if _gates[index] >= 0:
		_world.shapes.set_gate_open(_gates[index], open)
	if _is_attacker(index):
		attacker_changed.emit(index, open)
	else:
		tulip_changed.emit(index, open)
