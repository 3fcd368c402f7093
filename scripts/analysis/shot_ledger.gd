class_name ShotLedger
extends RefCounted
## What the balls of one analysis chunk came to, kept the same way whichever chunk fires
## them (PachinkoShotChunk, PlayedShotChunk): each ball's power band and the step it was
## fired on, its outcome in the chunk's tally (a pocket with its payout), and the density
## of balls per cell of the board.
##
## The density grid is the tally's, taken into this object while the chunk runs (open() /
## close()), so the per-ball sampling loop reads only this object's members: chunks run on
## worker threads side by side, and every look into another object takes an engine-wide
## lock in debug builds.

## The chunk's figures (whole numbers, merged in chunk order by the analysis).
var tally: AnalysisTally

var _payouts := PackedInt32Array()
## Per ball id (ids count up from 0 in a fresh world): its power band and the step its shot
## was fired on.
var _band_of := PackedInt32Array()
var _born := PackedInt32Array()
var _density := PackedInt64Array()
var _grid := Vector2i.ZERO


## A ledger for the pockets of `plan`'s board: the level's, then the bonus pockets.
func _init(plan: AnalysisPlan) -> void:
	var pockets := BonusGeometry.world_pockets(plan.level)
	tally = AnalysisTally.new(pockets.size(), plan.level.size)
	for pocket in pockets:
		var payout: int = pocket["payout"]
		_payouts.append(payout)


## Takes the tally's density grid for the run (see the class doc).
func open() -> void:
	_density = tally.density
	tally.density = PackedInt64Array()
	_grid = tally.grid_size


## Gives the density grid back to the tally: call when the run ends, early or not.
func close() -> void:
	tally.density = _density


## Ball `id` was fired in power band `band` on step `step`.
func fired(id: int, band: int, step: int) -> void:
	_band_of.resize(id + 1)
	_born.resize(id + 1)
	_band_of[id] = band
	_born[id] = step


## Ball `id`'s shot ended as `outcome` (AnalysisTally.Outcome); a POCKETED one in pocket
## `pocket`, which pays its payout.
func record(id: int, outcome: AnalysisTally.Outcome, pocket := -1) -> void:
	var payout := _payouts[pocket] if pocket >= 0 and pocket < _payouts.size() else 0
	tally.record(_band_of[id], outcome, pocket, payout)


## The balls of `world` fired before step `born_before` have flown too long: each is
## removed and counted STUCK. Returns their ids.
func drop_stuck(world: BallWorld, born_before: int) -> PackedInt32Array:
	var stuck := PackedInt32Array()
	for id: int in world.get_ids():
		if _born[id] < born_before:
			world.remove_ball(id)
			record(id, AnalysisTally.Outcome.STUCK)
			stuck.append(id)
	return stuck


## One density sample for the cell each of `positions` is in.
func sample(positions: PackedVector2Array) -> void:
	var inv_cell := 1.0 / AnalysisPlan.DENSITY_CELL
	var cols := _grid.x
	var rows := _grid.y
	for p: Vector2 in positions:
		var cx := int(p.x * inv_cell)
		var cy := int(p.y * inv_cell)
		if p.x >= 0.0 and p.y >= 0.0 and cx < cols and cy < rows:
			_density[cy * cols + cx] += 1


## One density sample for each cell in `cells` (a rail climb's, recorded once per power).
func add_samples(cells: PackedInt32Array) -> void:
	for c in cells:
		_density[c] += 1
