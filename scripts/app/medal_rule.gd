class_name MedalRule
extends RefCounted
## Where a maze board's medal times come from: the autoplay pilot's own games on it
## (tools/maze_pilot_table.gd --write-medals plays them and keeps what it measured in
## PILOT_RECORD, so tests/unit/test_medal_times.gd can check every board file against it).
## Easy medals from the pilot's easy game (seed 1), or its fastest hard win when faster (the
## hard run's way works with the holes asleep too), with bronze at least EASY_BRONZE_REACH
## times the easy game. Hard medals from the median of its hard
## wins (seeds 1..5): holes make the pilot wait and go round, so where they are live hard
## mode asks for more time, and never less than HARD_MIN_SHARE times easy's for the same
## medal. A board without holes has the same times in both modes.

## The pilot's measured times per board: {board_id: {"board": fingerprint, "easy": s,
## "hard": [s, ...]}} (JSON).
const PILOT_RECORD := "res://tools/maze_pilot_times.json"
## Hard medals from the easy time times this when the pilot never won hard mode.
const HARD_FALLBACK := 1.5
## Easy bronze is never under this many times the pilot's own easy game: on Garden Path a
## lucky fast hard win set bronze at 34.6 s while the pilot's easy games took 23 to 62 s
## (seeds 1-5), and a blind trial found the medals out of reach from the third board on.
const EASY_BRONZE_REACH := 1.5
## On a board with holes hard mode gives at least this many times easy's time for each medal.
## The pilot's hard wins alone left Cloister's hard gold 0.2 s over easy's and Garden Path's
## bronze the same in both (trial 6 found hard "nearly equal to easy"): the pilot plans every
## tilt and barely slows near a hole; a person does. Where the holes cost the pilot anything
## (maze rules 4 record, hard median over easy game) they cost it 1.03 to 5.2 times, a median
## of 1.21 (Garden 1.03, Courtyards 1.12, Tower 1.19, Labyrinth 1.21, The Deep 1.48,
## Crossroads 1.90, Undercroft 5.17): that median, rounded down, is the least hard gives.
const HARD_MIN_SHARE := 1.2


## [easy medal times, hard medal times] (each [gold, silver, bronze], see Medals) from the
## pilot's easy time (`easy` <= 0: it lost), its hard wins' times, and whether the board has
## holes.
static func medal_times(easy: float, hard_wins: PackedFloat64Array, has_holes: bool) -> Array:
	var sorted := hard_wins.duplicate()
	sorted.sort()
	var easy_base := easy
	if not sorted.is_empty() and (easy_base <= 0.0 or sorted[0] < easy_base):
		easy_base = sorted[0]
	var easy_times := Medals.from_pilot_time(easy_base) if easy_base > 0.0 else PackedFloat64Array()
	if easy > 0.0 and easy_times.size() == 3:
		easy_times[2] = maxf(easy_times[2], ceilf(easy * EASY_BRONZE_REACH * 10.0) / 10.0)
	if not has_holes:
		return [easy_times, easy_times.duplicate()]
	var hard_base := _median(sorted) if not sorted.is_empty() else easy_base * HARD_FALLBACK
	var hard_times := Medals.from_pilot_time(hard_base) if hard_base > 0.0 else PackedFloat64Array()
	# hard mode (holes live) always gives clearly more time than easy for the same medal
	if hard_times.size() == easy_times.size():
		for i in hard_times.size():
			var least := ceilf(easy_times[i] * HARD_MIN_SHARE * 10.0) / 10.0
			hard_times[i] = maxf(hard_times[i], least)
	return [easy_times, hard_times]


## What the pilot's record says a board was when it was measured: the board file's text
## without its medal_times line, as a SHA-256 (any other change to the board changes it).
static func fingerprint(board_text: String) -> String:
	var kept := PackedStringArray()
	for line in board_text.split("\n"):
		if not line.begins_with('{"medal_times"'):
			kept.append(line)
	return "\n".join(kept).sha256_text()


## A pilot time as the record keeps it (milliseconds).
static func rounded(seconds: float) -> float:
	return roundf(seconds * 1000.0) / 1000.0


## Gives a remade maze the medal times its file at `path` already holds: the times belong to
## the pilot's measurements (tools/maze_pilot_table.gd --write-medals), not to the recipe
## that builds the layout (the board generators call this before they save).
static func keep_file_medals(level: BoardLevel, path: String) -> void:
	if not level.is_maze() or not FileAccess.file_exists(path):
		return
	var old := BoardLoader.load_board(path)
	if old.level != null:
		level.medal_times_easy = old.level.medal_times_easy
		level.medal_times_hard = old.level.medal_times_hard


static func _median(sorted: PackedFloat64Array) -> float:
	var n := sorted.size()
	var half := floori(n * 0.5)
	if n % 2 == 1:
		return sorted[half]
	return (sorted[half - 1] + sorted[half]) * 0.5
