extends Control
## A board drawn small, fitted into this control's rect, for the level select.
## Uses the shared BoardPainter when the project has one (the same drawing as the editor),
## otherwise a simple drawing of its own. Special pins, holes and the goal differ by shape,
## not only by colour: special pins are diamonds, holes are crossed, the goal is a ringed star.

const BACK_COLOR := Color(0.06, 0.07, 0.11)
const FRAME_COLOR := Color(0.33, 0.4, 0.57)
const PIN_COLOR := Color(0.86, 0.72, 0.42)
const SPECIAL_COLOR := Color(1, 0.45, 0.35)
const WALL_COLOR := Color(0.74, 0.78, 0.88)
const GOAL_COLOR := Color(0.45, 0.9, 0.55)
const HOLE_COLOR := Color(0.02, 0.02, 0.03)
const BROKEN_COLOR := Color(0.55, 0.3, 0.28)
const MARGIN := 8.0

## The board to draw; null draws the "broken board" mark.
var level: BoardLevel = null:
	set(value):
		level = value
		queue_redraw()


func _draw() -> void:
	draw_rect(Rect2(Vector2.ZERO, size), BACK_COLOR)
	draw_rect(Rect2(Vector2.ZERO, size), FRAME_COLOR, false, 2.0)
	if level == null or level.size.x <= 0.0 or level.size.y <= 0.0:
		_draw_broken_mark()
		return
	var inner := Rect2(Vector2(MARGIN, MARGIN), size - Vector2(MARGIN, MARGIN) * 2.0)
	var scale_factor := minf(inner.size.x / level.size.x, inner.size.y / level.size.y)
	var offset := inner.position + (inner.size - level.size * scale_factor) * 0.5
	draw_set_transform(offset, 0.0, Vector2(scale_factor, scale_factor))
	if not _draw_with_board_painter():
		if level.kind == BoardLevel.Kind.MAZE:
			_draw_maze(scale_factor)
		else:
			_draw_pachinko(scale_factor)
	draw_set_transform(Vector2.ZERO)


## Delegates to the shared painter when it exists; false when it does not.
func _draw_with_board_painter() -> bool:
	for entry in ProjectSettings.get_global_class_list():
		if entry["class"] == &"BoardPainter":
			var painter: Script = load(entry["path"])
			if painter.has_method("paint"):
				painter.call("paint", self, level)
				return true
	return false


func _draw_pachinko(scale_factor: float) -> void:
	var line := 1.5 / scale_factor
	draw_circle(level.ring_center, level.ring_radius, Color(0.1, 0.13, 0.22))
	draw_arc(level.ring_center, level.ring_radius, 0.0, TAU, 96, WALL_COLOR, line * 2.0)
	var radius := maxf(level.pin_radius, 1.2 / scale_factor)
	for i in level.pins.size():
		var special := i < level.pin_special.size() and level.pin_special[i] != 0
		if special:
			_draw_diamond(level.pins[i], radius * 2.2, SPECIAL_COLOR)
		else:
			draw_circle(level.pins[i], radius, PIN_COLOR)


func _draw_maze(scale_factor: float) -> void:
	draw_rect(Rect2(Vector2.ZERO, level.size), Color(0.12, 0.1, 0.08))
	var width := maxf(level.wall_width, 2.0 / scale_factor)
	for i in range(0, level.walls.size() - 1, 2):
		draw_line(level.walls[i], level.walls[i + 1], WALL_COLOR, width)
	for hole in level.holes:
		draw_circle(hole, level.hole_radius, HOLE_COLOR)
		var arm := level.hole_radius * 0.6
		draw_line(hole - Vector2(arm, arm), hole + Vector2(arm, arm), SPECIAL_COLOR, width * 0.5)
		draw_line(hole - Vector2(arm, -arm), hole + Vector2(arm, -arm), SPECIAL_COLOR, width * 0.5)
	draw_arc(level.goal_center, level.goal_radius, 0.0, TAU, 48, GOAL_COLOR, width * 0.6)
	_draw_star(level.goal_center, level.goal_radius * 0.7, GOAL_COLOR)
	for start in level.ball_starts:
		draw_circle(start, level.ball_radius, Color(0.85, 0.88, 0.95))


func _draw_broken_mark() -> void:
	var centre := size * 0.5
	var arm := minf(size.x, size.y) * 0.18
	draw_line(centre - Vector2(arm, arm), centre + Vector2(arm, arm), BROKEN_COLOR, 6.0)
	draw_line(centre - Vector2(arm, -arm), centre + Vector2(arm, -arm), BROKEN_COLOR, 6.0)


func _draw_diamond(centre: Vector2, extent: float, color: Color) -> void:
	var points := PackedVector2Array(
		[
			centre + Vector2(0, -extent),
			centre + Vector2(extent, 0),
			centre + Vector2(0, extent),
			centre + Vector2(-extent, 0),
		]
	)
	draw_colored_polygon(points, color)


func _draw_star(centre: Vector2, radius: float, color: Color) -> void:
	var points := PackedVector2Array()
	for i in 10:
		var angle := -PI * 0.5 + i * PI / 5.0
		var reach := radius if i % 2 == 0 else radius * 0.45
		points.append(centre + Vector2(cos(angle), sin(angle)) * reach)
	draw_colored_polygon(points, color)
