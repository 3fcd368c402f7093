class_name AnalysisTally
extends RefCounted
## The raw counts of a pachinko analysis: what each shot did, per power band and pocket,
## and where balls went (a density grid). All counts are whole numbers, so merging chunk
## tallies gives the same totals in any order; the report turns them into figures.

## What a shot ended as.
enum Outcome { POCKETED, DRAINED, RETURNED, STUCK }

## The count arrays to_bytes() saves.
const SAVED_ARRAYS: Array[String] = [
	"band_shots",
	"band_returned",
	"band_drained",
	"band_stuck",
	"band_value",
	"band_value_sq",
	"band_pocket_hits",
	"band_entry",
	"density",
]

var pocket_count := 0
var band_count := AnalysisPlan.BAND_COUNT
## Per band: shots fired, shots rolled back, drained, stuck.
var band_shots := PackedInt64Array()
var band_returned := PackedInt64Array()
var band_drained := PackedInt64Array()
var band_stuck := PackedInt64Array()
## Per band: the sum of each shot's value (balls back in the cup: the pocket's payout, 1
## for a shot that rolled back, else 0) and of its square, for the sample variance.
var band_value := PackedInt64Array()
var band_value_sq := PackedInt64Array()
## Catches per band and pocket: index band * pocket_count + pocket.
var band_pocket_hits := PackedInt64Array()
## Where shots first met a pin, per band: shots per whole pixel of x, index
## band * entry_width + x (shots that met no pin are not counted).
var band_entry := PackedInt64Array()
var entry_width := 1
## Ball samples per density cell, row-major over grid_size.
var density := PackedInt64Array()
var grid_size := Vector2i.ZERO
## Simulation steps run and ball-steps simulated (for the speed figures).
var steps := 0
var ball_steps := 0


func _init(pockets: int = 0, board_size: Vector2 = Vector2.ZERO) -> void:
	pocket_count = maxi(pockets, 0)
	for counts: PackedInt64Array in _band_arrays():
		counts.resize(band_count)
	band_pocket_hits.resize(band_count * pocket_count)
	entry_width = maxi(ceili(board_size.x), 1)
	band_entry.resize(band_count * entry_width)
	grid_size = Vector2i(
		maxi(ceili(board_size.x / AnalysisPlan.DENSITY_CELL), 1),
		maxi(ceili(board_size.y / AnalysisPlan.DENSITY_CELL), 1)
	)
	density.resize(grid_size.x * grid_size.y)


## Records one finished shot fired in `band`: `outcome`, and for a catch its `pocket` and
## `payout`.
func record(band: int, outcome: Outcome, pocket := -1, payout := 0) -> void:
	band_shots[band] += 1
	var value := 0
	match outcome:
		Outcome.POCKETED:
			value = payout
			if pocket >= 0 and pocket < pocket_count:
				band_pocket_hits[band * pocket_count + pocket] += 1
		Outcome.RETURNED:
			value = 1
			band_returned[band] += 1
		Outcome.DRAINED:
			band_drained[band] += 1
		Outcome.STUCK:
			band_stuck[band] += 1
	band_value[band] += value
	band_value_sq[band] += value * value


## Records where a shot fired in `band` first met a pin (x in board pixels; NAN: none).
func record_entry(band: int, x: float) -> void:
	if is_finite(x):
		band_entry[band * entry_width + clampi(int(x), 0, entry_width - 1)] += 1


## The x (whole pixels) below which `share` (0..1) of `band`'s shots first met a pin, or
## -1 when none of its shots met one.
func entry_percentile(band: int, share: float) -> int:
	var counted := 0
	for x in entry_width:
		counted += band_entry[band * entry_width + x]
	if counted == 0:
		return -1
	var need := maxf(share * counted, 1.0)
	var running := 0
	for x in entry_width:
		running += band_entry[band * entry_width + x]
		if running >= need:
			return x
	return entry_width - 1


## Adds another tally's counts (same board) to this one.
func merge(other: AnalysisTally) -> void:
	var mine := _band_arrays()
	var theirs := other._band_arrays()
	for a in mine.size():
		_add_into(mine[a], theirs[a])
	_add_into(band_pocket_hits, other.band_pocket_hits)
	_add_into(band_entry, other.band_entry)
	_add_into(density, other.density)
	steps += other.steps
	ball_steps += other.ball_steps


## The counts as bytes (var_to_bytes of plain data, no objects): what an analysis worker
## process hands back to the editor (AnalysisWorker). from_bytes() reads them.
func to_bytes() -> PackedByteArray:
	var fields := {"pocket_count": pocket_count, "entry_width": entry_width}
	fields["grid_size"] = grid_size
	fields["steps"] = steps
	fields["ball_steps"] = ball_steps
	for key in SAVED_ARRAYS:
		fields[key] = get(key)
	return var_to_bytes(fields)


## A tally read back from to_bytes(), or null when `bytes` are not one.
static func from_bytes(bytes: PackedByteArray) -> AnalysisTally:
	var data: Variant = bytes_to_var(bytes) if bytes.size() >= 4 else null
	if not data is Dictionary:
		return null
	var fields: Dictionary = data
	var tally := AnalysisTally.new()
	if not fields.get("grid_size") is Vector2i:
		return null
	for key in SAVED_ARRAYS:
		if not fields.get(key) is PackedInt64Array:
			return null
		tally.set(key, fields[key])
	var pockets: int = fields.get("pocket_count", 0)
	var width: int = fields.get("entry_width", 1)
	var steps_run: int = fields.get("steps", 0)
	var ball_steps_run: int = fields.get("ball_steps", 0)
	tally.pocket_count = pockets
	tally.entry_width = width
	tally.grid_size = fields["grid_size"]
	tally.steps = steps_run
	tally.ball_steps = ball_steps_run
	var bands := tally.band_shots.size()
	if (
		bands != tally.band_count
		or tally.band_pocket_hits.size() != bands * tally.pocket_count
		or tally.band_entry.size() != bands * tally.entry_width
		or tally.density.size() != tally.grid_size.x * tally.grid_size.y
	):
		return null
	return tally


## Shots recorded in every band.
func total_shots() -> int:
	return _sum(band_shots)


## Catches of `pocket` over every band.
func pocket_hits(pocket: int) -> int:
	var hits := 0
	for band in band_count:
		hits += band_pocket_hits[band * pocket_count + pocket]
	return hits


## Catches of `pocket` in `band`.
func hits_in_band(band: int, pocket: int) -> int:
	return band_pocket_hits[band * pocket_count + pocket]


static func total(counts: PackedInt64Array) -> int:
	return _sum(counts)


func _band_arrays() -> Array[PackedInt64Array]:
	# Packed arrays are values: hand back the members themselves through this one list.
	return [band_shots, band_returned, band_drained, band_stuck, band_value, band_value_sq]


static func _sum(counts: PackedInt64Array) -> int:
	var s := 0
	for c in counts:
		s += c
	return s


static func _add_into(into: PackedInt64Array, from: PackedInt64Array) -> void:
	for i in mini(into.size(), from.size()):
		into[i] += from[i]
