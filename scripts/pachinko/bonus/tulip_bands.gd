class_name TulipBands
extends RefCounted
## The handle strengths that reach each shipped machine's tulips while they are open: when
## one opens the launcher marks its band on the bar and the dial and says "Tulip open:
## power 55–65", a reason to turn the handle mid-game (trial 7: holding one strength was
## all there was to do). During a jackpot's rounds the attacker's band (AttackerBands)
## comes first. Measured with tools/tulip_band.gd (catches while open per 100 shots, seeds
## 1 and 2, 100 shots a strength every 5 points; the strengths within half of the best).
## A board with no entry (a player's own) says nothing.

## Board id -> bonus pocket index -> the band (lowest, highest strength).
const BANDS := {
	# tulips 1-4: top left, top right, low left, low right (best 16, 54.5, 51.5, 32 per 100)
	"pachinko_tulips":
	{0: Vector2i(80, 85), 1: Vector2i(40, 65), 2: Vector2i(95, 100), 3: Vector2i(30, 60)},
	# left, right (best 21 at 90, 37.5 at 30)
	"pachinko_fever": {2: Vector2i(80, 95), 3: Vector2i(30, 45)},
	# top left, top right, low left, low right (best 15.5, 54.5, 8.5, 11 per 100)
	"pachinko_hanami":
	{3: Vector2i(75, 85), 4: Vector2i(35, 55), 5: Vector2i(80, 100), 6: Vector2i(40, 75)},
}


## The band that reaches tulip `index` (a bonus pocket index) on `level`; Vector2i.ZERO
## when none is known.
static func band_of(level: BoardLevel, index: int) -> Vector2i:
	var bands: Dictionary = BANDS.get(level.board_id, {})
	return bands.get(index, Vector2i.ZERO)


## The launcher's line for `band`, in the player's words ("Tulip open: power 55–65"), ""
## for none.
static func words(band: Vector2i) -> String:
	if band == Vector2i.ZERO:
		return ""
	return "Tulip open: power %d–%d" % [band.x, band.y]


## What the launcher marks on `level` now: the attacker's band while `rounds_on`, else the
## band of the last tulip in `open_tulips` (bonus indices, in the order they opened) that
## has one. {"band": Vector2i, "words": String}; a ZERO band and "" for none.
static func aim(level: BoardLevel, rounds_on: bool, open_tulips: Array[int]) -> Dictionary:
	var attacker := AttackerBands.band_of(level)
	if rounds_on and attacker != Vector2i.ZERO:
		return {"band": attacker, "words": AttackerBands.words(attacker)}
	for k in range(open_tulips.size() - 1, -1, -1):
		var band := band_of(level, open_tulips[k])
		if band != Vector2i.ZERO:
			return {"band": band, "words": words(band)}
	return {"band": Vector2i.ZERO, "words": ""}
