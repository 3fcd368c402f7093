@tool
extends RefCounted
## Live red ghosts: would placing these items give the board an error it does not have
## yet (a pocket over another, a hole on a start, a wall leaving a gap a ball wedges in)?
## The placement is tried on a copy of the board with the same action the click commits,
## and the copy is validated; the answer is kept for the last placement asked until the
## board changes, so a ghost that does not move costs nothing.

const AddItemsAction := preload("res://addons/board_editor/actions/add_items_action.gd")

var _asked := ""
var _answer := false


## Forgets the kept answer (the board changed).
func forget() -> void:
	_asked = ""


## True when adding `data` (a BoardItems set, already mirrored) to `level` adds an error.
func adds_error(level: BoardLevel, data: Dictionary) -> bool:
	if not level.changed.is_connected(forget):
		level.changed.connect(forget)
	var asked := "%d|%s" % [level.get_instance_id(), var_to_str(data)]
	if asked == _asked:
		return _answer
	_asked = asked
	_answer = would_add_error(level, data)
	return _answer


## The check itself, uncached.
static func would_add_error(level: BoardLevel, data: Dictionary) -> bool:
	var trial := level.duplicate_level()
	var before := BoardValidator.errors(trial).size()
	AddItemsAction.new(trial, data, "Try").do()
	return BoardValidator.errors(trial).size() > before


## True when the goal moved to `spot` would sit on a wall (a wall's centre line runs inside
## its ring; a ring that only grazes a wall's side, as on the Classic maze, is fine), hold a
## ball start (the ball would start in the goal) or cover a black hole: its ghost shows red
## there. The board check warns of the last two.
static func goal_blocked(level: BoardLevel, spot: Vector2) -> bool:
	var radius := level.goal_radius
	for w in range(0, level.walls.size() - 1, 2):
		var near := Geometry2D.get_closest_point_to_segment(
			spot, level.walls[w], level.walls[w + 1]
		)
		if near.distance_to(spot) < radius:
			return true
	for start in level.ball_starts:
		if start.distance_to(spot) < radius:
			return true
	for hole in level.holes:
		if hole.distance_to(spot) < radius + level.hole_radius:
			return true
	return false
