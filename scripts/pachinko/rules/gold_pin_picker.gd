class_name GoldPinPicker
extends RefCounted
## Chooses a set of gold pins so that no one held strength reaches them all: only pins some
## power touches (PinReach), taken in turn from different zones of the field (left, middle
## and right; high and low; and around the windmills and bonus pockets), apart from each
## other, and then checked against every handle window (a strength ± LaunchHandle.JITTER):
## while one window would touch every pin of the set, a pin it touches is swapped for one it
## does not. The draws come from the caller's generator, so one seed gives one set.

## A gold pin this close to a windmill's hub or a bonus pocket belongs to the pieces' zone.
const NEAR_PIECE := 60.0
## Gold pins of one set stand at least this far apart (pixels), while the field allows.
const MIN_APART := 45.0
## The pieces' zone's index (the six field cells come first).
const PIECES_ZONE := 6
## A gold pin is touched by at least this many measured powers (one power alone is a
## needle the handle's spring rarely threads), while the field has enough such pins.
const MIN_POWERS := 3


## How many gold pins a set of `level` has: 6 on a small field, up to 8 on a crowded one.
static func set_size(reach: PinReach) -> int:
	return clampi(6 + floori(reach.reached_pins().size() / 200.0), 6, 8)


## A set of `size` gold pins of `level` (pin indexes), drawn with `rng`.
static func pick(
	level: BoardLevel, reach: PinReach, size: int, rng: RandomNumberGenerator
) -> PackedInt32Array:
	var candidates := _candidates(reach, size)
	_shuffle(candidates, rng)
	var by_zone: Array[PackedInt32Array] = []
	for z in PIECES_ZONE + 1:
		by_zone.append(PackedInt32Array())
	for pin in candidates:
		var z := zone_of(level, pin)
		by_zone[z].append(pin)
	var zones := PackedInt32Array(range(PIECES_ZONE + 1))
	_shuffle(zones, rng)
	var chosen := PackedInt32Array()
	for apart: float in [MIN_APART, 0.0]:  # spread first; crowd only if the field is small
		var progress := true
		while chosen.size() < size and progress:
			progress = false
			for z in zones:
				var pin := _first_fitting(level, by_zone[z], chosen, apart)
				if pin >= 0 and chosen.size() < size:
					chosen.append(pin)
					progress = true
	_break_windows(reach, chosen, candidates)
	return chosen


## The pins a set is drawn from: those MIN_POWERS powers touch (every reached pin when
## fewer than three sets' worth do).
static func _candidates(reach: PinReach, size: int) -> PackedInt32Array:
	var all := reach.reached_pins()
	var sure := PackedInt32Array()
	for pin in all:
		if reach.powers_reaching(pin).size() >= MIN_POWERS:
			sure.append(pin)
	return sure if sure.size() >= size * 3 else all


## The zone of pin `pin`: the pieces' zone near a windmill or bonus pocket, else one of six
## cells (left / middle / right thirds of the ring, above / below its centre).
static func zone_of(level: BoardLevel, pin: int) -> int:
	var at := level.pins[pin]
	for mill in level.windmills:
		if at.distance_to(mill.position) < NEAR_PIECE:
			return PIECES_ZONE
	for piece in level.bonus_pockets:
		if at.distance_to(piece.position) < NEAR_PIECE:
			return PIECES_ZONE
	var radius := maxf(level.ring_radius, 1.0)
	var column := clampi(int((at.x - level.ring_center.x + radius) / (2.0 * radius) * 3.0), 0, 2)
	var row := 0 if at.y < level.ring_center.y else 1
	return row * 3 + column


## The strengths 0..100 (whole points) whose handle window touches every pin of `pins`.
static func covering_strengths(reach: PinReach, pins: PackedInt32Array) -> PackedInt32Array:
	var out := PackedInt32Array()
	for strength in 101:
		if _window_touches_all(reach, strength, pins):
			out.append(strength)
	return out


# While some strength's window touches every chosen pin, swap one it touches for a candidate
# it misses (a candidate no other window then covers is preferred by trying them in order).
static func _break_windows(
	reach: PinReach, chosen: PackedInt32Array, candidates: PackedInt32Array
) -> void:
	for attempt in 8:
		var covering := covering_strengths(reach, chosen)
		if covering.is_empty() or chosen.is_empty():
			return
		var window := _window_pins(reach, covering[0])
		var swapped := false
		for pin in candidates:
			if not window.has(pin) and not chosen.has(pin):
				chosen[chosen.size() - 1 - attempt % chosen.size()] = pin
				swapped = true
				break
		if not swapped:
			return


static func _window_touches_all(reach: PinReach, strength: int, pins: PackedInt32Array) -> bool:
	var window := _window_pins(reach, strength)
	for pin in pins:
		if not window.has(pin):
			return false
	return true


static func _window_pins(reach: PinReach, strength: int) -> Dictionary[int, bool]:
	var out: Dictionary[int, bool] = {}
	var jitter := int(LaunchHandle.JITTER)
	for p in range(maxi(strength - jitter, 0), mini(strength + jitter, 100) + 1):
		for pin in reach.pins_at(p):
			out[pin] = true
	return out


static func _first_fitting(
	level: BoardLevel, pool: PackedInt32Array, chosen: PackedInt32Array, apart: float
) -> int:
	for pin in pool:
		if chosen.has(pin):
			continue
		var clear := true
		for other in chosen:
			if level.pins[pin].distance_to(level.pins[other]) < apart:
				clear = false
				break
		if clear:
			return pin
	return -1


static func _shuffle(values: PackedInt32Array, rng: RandomNumberGenerator) -> void:
	for i in range(values.size() - 1, 0, -1):
		var j := rng.randi_range(0, i)
		var keep := values[i]
		values[i] = values[j]
		values[j] = keep
