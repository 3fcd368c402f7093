@tool
extends RefCounted
## Draws why the pilot lost its maze games on the board: where each lost game's balls ended
## (small rings in the reason's colour), and one marker per loss entry (MazeLosses) with a
## tag: a crossed square for a trapped ball (and a line to the gap that shuts it in), a
## diamond for a stuck one, a ring round the hole that caught one, a clock for time that
## ran out.

const MazeLossWords := preload("res://addons/board_editor/analysis/maze_loss_words.gd")
const TRAPPED_INK := Color(1.0, 0.25, 0.45)
const STUCK_INK := Color(1.0, 0.62, 0.15)
const HOLE_INK := Color(1.0, 0.42, 0.38)
const TIMEOUT_INK := Color(0.75, 0.78, 0.85)
const CARD_INK := Color(0.05, 0.06, 0.09, 0.86)
const FONT_SIZE := 13
## Marker half size, screen px.
const MARK := 8.0


## The colour of a loss reason.
static func ink(reason: String) -> Color:
	match reason:
		"trapped":
			return TRAPPED_INK
		"stuck":
			return STUCK_INK
		"hole":
			return HOLE_INK
	return TIMEOUT_INK


## Draws the lost games of `report` (a MazeAnalysis report) for `level`.
static func draw(
	canvas: Control, to_screen: Transform2D, level: BoardLevel, report: Dictionary
) -> void:
	var games: Array = report.get("games", [])
	for game: Dictionary in games:
		var reason := str(game.get("reason", "won"))
		if reason == "won":
			continue
		var ends: Array = game.get("ends", [])
		for end: Variant in ends:
			var p := _point(end)
			if p.is_finite():
				canvas.draw_arc(to_screen * p, 3.0, 0.0, TAU, 12, Color(ink(reason), 0.7), 1.0)
	var losses: Array = report.get("losses", [])
	for entry: Dictionary in losses:
		_draw_entry(canvas, to_screen, level, entry)


static func _draw_entry(
	canvas: Control, to_screen: Transform2D, level: BoardLevel, entry: Dictionary
) -> void:
	var at := _point(entry.get("at", []))
	if not at.is_finite():
		return
	var reason := str(entry.get("reason", ""))
	var color := ink(reason)
	var c := to_screen * at
	match reason:
		"trapped":
			var gap := _point(entry.get("gap", []))
			if gap.is_finite():
				canvas.draw_dashed_line(c, to_screen * gap, color, 1.5, 5.0)
				canvas.draw_arc(to_screen * gap, MARK * 0.8, 0.0, TAU, 20, color, 2.5, true)
			canvas.draw_rect(
				Rect2(c - Vector2(MARK, MARK), Vector2(MARK, MARK) * 2), color, false, 2.5
			)
			canvas.draw_line(c - Vector2(MARK, MARK), c + Vector2(MARK, MARK), color, 2.0)
			canvas.draw_line(c + Vector2(-MARK, MARK), c + Vector2(MARK, -MARK), color, 2.0)
		"stuck":
			var diamond := PackedVector2Array(
				[
					c + Vector2(0, -MARK),
					c + Vector2(MARK, 0),
					c + Vector2(0, MARK),
					c + Vector2(-MARK, 0),
					c + Vector2(0, -MARK)
				]
			)
			canvas.draw_polyline(diamond, color, 2.5, true)
		"hole":
			var radius := (level.hole_radius + 6.0) * to_screen.get_scale().x
			canvas.draw_arc(c, maxf(radius, MARK), 0.0, TAU, 40, color, 2.5, true)
		_:
			canvas.draw_arc(c, MARK, 0.0, TAU, 24, color, 2.0, true)
			canvas.draw_line(c, c + Vector2(0, -MARK * 0.7), color, 2.0)
			canvas.draw_line(c, c + Vector2(MARK * 0.5, 0), color, 2.0)
	_tag(canvas, c + Vector2(MARK + 5.0, FONT_SIZE * 0.4), MazeLossWords.tag(entry), color)


static func _tag(canvas: Control, at: Vector2, text: String, color: Color) -> void:
	var font := ThemeDB.fallback_font
	var width := font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, FONT_SIZE).x
	canvas.draw_rect(Rect2(at - Vector2(3, FONT_SIZE), Vector2(width + 6, FONT_SIZE + 4)), CARD_INK)
	canvas.draw_string(font, at, text, HORIZONTAL_ALIGNMENT_LEFT, -1, FONT_SIZE, color)


static func _point(value: Variant) -> Vector2:
	var point: Array = value if value is Array else []
	if point.size() != 2:
		return Vector2(INF, INF)
	var x: float = point[0]
	var y: float = point[1]
	return Vector2(x, y)
