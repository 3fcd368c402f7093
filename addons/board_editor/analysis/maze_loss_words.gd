@tool
extends RefCounted
## Says why the autoplay pilot lost its maze games, in a designer's words, from the maze
## analysis's grouped losses (MazeLosses): "3 of 12 games: a ball was stuck near
## (120, 340) for 20 s".

## Most loss lines the dock shows; the rest are counted in one more line.
const MAX_LINES := 4


## The dock's lines for `report` (a MazeAnalysis report): one per loss entry, most games
## first; none when every game was won or the report predates the reasons.
static func lines(report: Dictionary) -> PackedStringArray:
	var out := PackedStringArray()
	var losses: Array = report.get("losses", [])
	var total := _games(report)
	for k in mini(losses.size(), MAX_LINES):
		var entry: Dictionary = losses[k]
		out.append(line(entry, total))
	if losses.size() > MAX_LINES:
		var more := 0
		for k in range(MAX_LINES, losses.size()):
			var entry: Dictionary = losses[k]
			more += _count(entry, "games")
		out.append("%d more lost game%s elsewhere (see the board)." % [more, _s(more)])
	return out


## One loss entry in words; `total` is the games played in both modes.
static func line(entry: Dictionary, total: int) -> String:
	var games := _count(entry, "games")
	var at := place(entry.get("at", []))
	var seconds: float = entry.get("seconds", 0.0)
	var text := "%d of %d games: " % [games, total]
	match str(entry.get("reason", "")):
		"trapped":
			text += "a ball was trapped near %s, with no way out wide enough for it" % at
			var gap: Array = entry.get("gap", [])
			if gap.size() == 2:
				text += " (the gap at %s is narrower than a ball)" % place(gap)
		"stuck":
			text += "a ball was stuck near %s for %d s" % [at, roundi(seconds)]
		"hole":
			text += "a ball fell into hole %d at %s" % [_count(entry, "hole"), at]
		"timeout":
			text += "time ran out (%d s) with a ball still near %s" % [roundi(seconds), at]
		_:
			text += "lost near %s" % at
	return text + _mode_note(entry, games) + "."


## A short tag for the marker on the board: "trapped ×6", "stuck ×3".
static func tag(entry: Dictionary) -> String:
	var words := {
		"trapped": "trapped", "stuck": "stuck", "hole": "fell in", "timeout": "time ran out"
	}
	return "%s ×%d" % [words.get(str(entry.get("reason", "")), "lost"), _count(entry, "games")]


## A board point as "(120, 340)".
static func place(at: Variant) -> String:
	var point: Array = at if at is Array else []
	if point.size() != 2:
		return "(?)"
	var x: float = point[0]
	var y: float = point[1]
	return "(%d, %d)" % [roundi(x), roundi(y)]


static func _mode_note(entry: Dictionary, games: int) -> String:
	if _count(entry, "hard") == games and str(entry.get("reason")) != "hole":
		return " (hard mode)"
	if _count(entry, "easy") == games:
		return " (easy mode)"
	return ""


static func _games(report: Dictionary) -> int:
	var total := 0
	for mode: String in ["easy", "hard"]:
		var figures: Dictionary = report.get(mode, {})
		total += _count(figures, "games")
	return total


# A whole number from a report (JSON read back from disk gives floats).
static func _count(values: Dictionary, key: String) -> int:
	var value: Variant = values.get(key, 0)
	if value is int:
		var whole: int = value
		return whole
	if value is float:
		var number: float = value
		return roundi(number)
	return 0


static func _s(count: int) -> String:
	return "" if count == 1 else "s"
