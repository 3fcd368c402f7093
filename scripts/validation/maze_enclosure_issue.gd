class_name MazeEnclosureIssue
extends RefCounted
## The words of a maze board that cannot be won: one BoardIssue per cause MazeEnclosure finds,
## naming the goal or the ball starts closed in and the walls that close them (drawn in the
## problem's colour by the editor, BoardIssue.segments).

const ERROR := BoardIssue.Severity.ERROR


## The problem for one cause of MazeEnclosure: the goal closed in ("goal_closed_in", marked
## at the goal) or starts closed in ("start_cannot_reach_goal", marked at the first start),
## naming the walls round it; the problem covers the walls and the goal (and the starts
## when they are the ones closed in).
static func of(level: BoardLevel, cause: Dictionary, start_total: int) -> BoardIssue:
	var starts: PackedInt32Array = cause["starts"]
	var walls: PackedInt32Array = cause["walls"]
	var around_goal: bool = cause["goal"]
	var along_edge: bool = cause["edge"]
	var start_ids: Array[String] = []
	for i in starts:
		start_ids.append(str(ItemIds.of(level, "ball_starts", i)))
	var wall_ids: Array[String] = []
	var segments := PackedVector2Array()
	var covers := Rect2(level.goal_center, Vector2.ZERO).grow(level.goal_radius)
	for w in walls:
		wall_ids.append(str(ItemIds.of(level, "walls", w)))
		segments.append(level.walls[w * 2])
		segments.append(level.walls[w * 2 + 1])
		covers = covers.expand(level.walls[w * 2]).expand(level.walls[w * 2 + 1])
	if not around_goal:  # closed-in starts are framed with the goal they miss
		for i in starts:
			covers = covers.expand(level.ball_starts[i])
	var closers := _closers(wall_ids, along_edge)
	var issue: BoardIssue
	if around_goal:
		var who := "ball start %s cannot" % _and_list(start_ids)
		if starts.size() > 1:
			who = "ball starts %s cannot" % _and_list(start_ids)
		if starts.size() == start_total and start_total > 1:
			who = "none of the %d ball starts can" % start_total
		issue = BoardIssue.new(
			ERROR,
			"The goal is closed in by %s: %s roll to it." % [closers, who],
			level.goal_center,
			"goal_closed_in"
		)
	else:
		var many := starts.size() > 1
		issue = BoardIssue.new(
			ERROR,
			(
				"Ball start%s %s cannot roll to the goal: %s close%s %s in."
				% [
					"s" if many else "",
					_and_list(start_ids),
					closers,
					"" if wall_ids.size() + (1 if cause["edge"] else 0) > 1 else "s",
					"them" if many else "it"
				]
			),
			level.ball_starts[starts[0]],
			"start_cannot_reach_goal"
		)
	issue.area = covers.abs()
	issue.segments = segments
	return issue


# "walls 3, 7 and 9", "wall 4 and the board's edge", "the board's edge".
static func _closers(wall_ids: Array[String], edge: bool) -> String:
	var parts: Array[String] = []
	if not wall_ids.is_empty():
		parts.append("wall%s %s" % ["s" if wall_ids.size() > 1 else "", _and_list(wall_ids)])
	if edge or parts.is_empty():
		parts.append("the board's edge")
	return " and ".join(parts)


# "1", "1 and 2", "1, 2 and 3".
static func _and_list(words: Array[String]) -> String:
	if words.size() <= 1:
		return "".join(words)
	return ", ".join(words.slice(0, -1)) + " and " + words[-1]
