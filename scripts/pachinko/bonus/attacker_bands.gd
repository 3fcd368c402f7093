class_name AttackerBands
extends RefCounted
## The handle strengths that feed each shipped machine's attacker best during a jackpot's
## rounds: the launcher marks them on its bar and dial and says "Feed the attacker: stream at
## 75–85" while the rounds last. Measured with tools/attacker_band.gd (catches a round by
## power, seeds 1 and 2, rules 6): Fever 1.5 at 60 against 3.5 / 4.85 / 3.25 at 75 / 80 /
## 85; Hanami 1.0 at 60 against 3.95 / 6.05 / 3.25. A board with no entry (a player's own)
## says nothing: its best strength is the player's to find.

## Board id -> the band (lowest, highest strength).
const BANDS := {
	"pachinko_fever": Vector2i(75, 85),
	"pachinko_hanami": Vector2i(75, 85),
}


## The band on `level`; Vector2i.ZERO when it has none.
static func band_of(level: BoardLevel) -> Vector2i:
	return BANDS.get(level.board_id, Vector2i.ZERO)


## The launcher's line for `band`, in the player's words ("Feed the attacker: stream at
## 75–85"), "" for none. The band is the handle's, streaming: trial 9 fired single shots at
## 80 for five rounds and caught nothing. Single shots one a second on Fever (seed 1, about
## three rounds each) caught 0 a round at 70, 80, 85 and 95 and 12 at 90: the flipper's
## power gives other speeds than the handle's, so the line names the stream.
static func words(band: Vector2i) -> String:
	if band == Vector2i.ZERO:
		return ""
	return "Feed the attacker: stream at %d–%d" % [band.x, band.y]
