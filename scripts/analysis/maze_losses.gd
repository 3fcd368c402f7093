class_name MazeLosses
extends RefCounted
## Groups the maze analysis's lost games by why and where they were lost, for the dock and
## the board overlay: "3 of 12 games: a ball was stuck near (120, 340) for 20 s". Games lost
## for the same reason with their ball in the same patch of the board (one maze cell and
## its walls) are one entry. A trapped ball's entry names the gap narrower than a ball
## (MazeGaps) that shuts its part of the board, when one does.

## The reasons in the order the dock lists entries of equal count.
const REASONS: Array[String] = ["trapped", "stuck", "hole", "timeout"]


## The lost games of `games` (MazeAnalysis outcomes) grouped: each entry has "reason",
## "at" (the mean place, [x, y]), "games", "easy", "hard", "seconds" (mean seconds without
## progress before the game was given up, or played), "hole" (the hole's id, for "hole")
## and "gap" ([x, y] of the narrow gap, for "trapped", or []). Most games first.
static func group(
	level: BoardLevel, games: Array[Dictionary], flood: MazeFlood, gaps: Array[BoardIssue]
) -> Array[Dictionary]:
	var patch := maxf(level.path_width + level.wall_width, level.ball_radius * 4.0)
	var by_key := {}
	var entries: Array[Dictionary] = []
	for game in games:
		var reason: String = game.get("reason", "won")
		var at: Array = game.get("at", [])
		if reason == "won" or reason == "no_board" or at.size() != 2:
			continue
		var x: float = at[0]
		var y: float = at[1]
		var place := Vector2(x, y)
		var key := "%s %s" % [reason, (place / patch).floor()]
		if not by_key.has(key):
			by_key[key] = entries.size()
			entries.append(_entry(level, reason, game))
		var entry: Dictionary = entries[by_key[key]]
		entry["games"] += 1
		entry["hard" if game.get("hard", false) else "easy"] += 1
		entry["_sum"] += place
		var seconds: float = game.get("idle_s" if reason == "stuck" else "seconds", 0.0)
		entry["_seconds"] += seconds
	for entry in entries:
		var count: int = entry["games"]
		var mean: Vector2 = entry["_sum"] / float(count)
		entry["at"] = [snappedf(mean.x, 0.1), snappedf(mean.y, 0.1)]
		var seconds_sum: float = entry["_seconds"]
		entry["seconds"] = snappedf(seconds_sum / float(count), 0.1)
		entry.erase("_sum")
		entry.erase("_seconds")
		if entry["reason"] == "trapped":
			entry["gap"] = _gap_shutting(level, mean, flood, gaps)
	entries.sort_custom(_before)
	return entries


static func _entry(level: BoardLevel, reason: String, game: Dictionary) -> Dictionary:
	var entry := {
		"reason": reason,
		"games": 0,
		"easy": 0,
		"hard": 0,
		"_sum": Vector2.ZERO,
		"_seconds": 0.0,
	}
	var hole: int = game.get("hole", -1)
	if reason == "hole" and hole >= 0:
		entry["hole"] = ItemIds.of(level, "holes", hole)
	return entry


static func _before(a: Dictionary, b: Dictionary) -> bool:
	if a["games"] != b["games"]:
		return a["games"] > b["games"]
	return REASONS.find(a["reason"]) < REASONS.find(b["reason"])


# The narrow gap that borders the part of the board a ball at `at` is shut in (its flood
# region reaches a ball's width of the gap), the nearest to the ball; [] for none.
static func _gap_shutting(
	level: BoardLevel, at: Vector2, flood: MazeFlood, gaps: Array[BoardIssue]
) -> Array:
	var label := flood.region_near(at)
	if label < 0:
		return []
	var reach := level.ball_radius * 2.0 + flood.cell * 2.0
	var nearest := INF
	var found := []
	for gap in gaps:
		if (
			gap.position.distance_to(at) >= nearest
			or not _region_near(flood, gap.position, reach, label)
		):
			continue
		nearest = gap.position.distance_to(at)
		found = [snappedf(gap.position.x, 0.1), snappedf(gap.position.y, 0.1)]
	return found


static func _region_near(flood: MazeFlood, at: Vector2, reach: float, label: int) -> bool:
	var steps := ceili(reach / flood.cell)
	for dy in range(-steps, steps + 1):
		for dx in range(-steps, steps + 1):
			var p := at + Vector2(dx, dy) * flood.cell
			if p.distance_to(at) <= reach and flood.region_at(p) == label:
				return true
	return false
