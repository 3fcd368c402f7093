@tool
extends RefCounted
## Small drawing helpers for the editor overlay: board pixels in, screen pixels out, with a
## minimum on-screen size so tiny pins stay visible when zoomed out.

const HitTest := preload("res://addons/board_editor/core/hit_test.gd")

const SELECT_COLOR := Color(0.35, 0.75, 1.0)
const GHOST_COLOR := Color(0.3, 0.95, 0.5, 0.8)
const ERROR_COLOR := Color(1.0, 0.25, 0.2)
const WARNING_COLOR := Color(1.0, 0.7, 0.15)
const HANDLE_COLOR := Color(1.0, 0.85, 0.3)
const BLOCKED_COLOR := Color(1.0, 0.25, 0.2, 0.85)
const MIN_RADIUS := 3.0
## Handle squares (screen px): big enough to see and grab on a busy board.
const HANDLE_SIZE := 12.0
const HOT_HANDLE_SIZE := 15.0
const LABEL_FONT_SIZE := 14


## A circle of `radius` board pixels at `center`.
static func circle(
	canvas: Control,
	to_screen: Transform2D,
	center: Vector2,
	radius: float,
	color: Color,
	filled := false,
	width := 1.5
) -> void:
	var r := maxf(radius * to_screen.get_scale().x, MIN_RADIUS)
	if filled:
		canvas.draw_circle(to_screen * center, r, color)
	else:
		canvas.draw_arc(to_screen * center, r, 0.0, TAU, 32, color, width, true)


## Ghost pins: where a tool would put pins; red where a pin would overlap one already on
## `level`, leave it a gap a ball sticks in, or stand outside the ring or in the launch rail
## (HitTest.pin_blocked).
static func ghost_points(
	canvas: Control,
	to_screen: Transform2D,
	points: PackedVector2Array,
	radius: float,
	level: BoardLevel = null
) -> void:
	for point in points:
		var blocked := level != null and HitTest.pin_blocked(level, point)
		circle(canvas, to_screen, point, radius, BLOCKED_COLOR if blocked else GHOST_COLOR, true)
		if blocked:
			circle(canvas, to_screen, point, radius + 3.0, BLOCKED_COLOR, false, 1.5)


## Text on a dark box, readable on the dark pachinko field and the light maze floor alike.
static func label(canvas: Control, at: Vector2, text: String, color := Color.WHITE) -> void:
	var font := ThemeDB.fallback_font
	var size := font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, LABEL_FONT_SIZE)
	var box := Rect2(at + Vector2(-4, -size.y + 2), size + Vector2(8, 6))
	canvas.draw_rect(box, Color(0.05, 0.05, 0.08, 0.82), true)
	canvas.draw_rect(box, Color(1, 1, 1, 0.25), false, 1.0)
	canvas.draw_string(font, at, text, HORIZONTAL_ALIGNMENT_LEFT, -1, LABEL_FONT_SIZE, color)


## A line between two board points.
static func line(
	canvas: Control, to_screen: Transform2D, a: Vector2, b: Vector2, color: Color, width := 1.5
) -> void:
	canvas.draw_line(to_screen * a, to_screen * b, color, width, true)


## A square handle at a board point.
static func handle(canvas: Control, to_screen: Transform2D, at: Vector2, hot: bool) -> void:
	var size := HOT_HANDLE_SIZE if hot else HANDLE_SIZE
	var rect := Rect2(to_screen * at - Vector2.ONE * size * 0.5, Vector2.ONE * size)
	canvas.draw_rect(rect, HANDLE_COLOR if hot else Color(1, 1, 1), true)
	canvas.draw_rect(rect, Color(0, 0, 0, 0.9), false, 2.0)


## A circular arc on the board (angles in radians), drawn as a polyline.
static func board_arc(
	canvas: Control,
	to_screen: Transform2D,
	center: Vector2,
	radius: float,
	from: float,
	to: float,
	color: Color,
	width := 2.0
) -> void:
	var points := PackedVector2Array()
	var steps := maxi(8, int(absf(to - from) * 24.0))
	for i in steps + 1:
		var angle := lerpf(from, to, float(i) / float(steps))
		points.append(to_screen * (center + Vector2.from_angle(angle) * radius))
	canvas.draw_polyline(points, color, width, true)


## An arc's centre mark: a cross in a ring, and dashed spokes to the arc's two ends.
static func center_mark(
	canvas: Control, to_screen: Transform2D, center: Vector2, ends: PackedVector2Array
) -> void:
	var at := to_screen * center
	var color := Color(1.0, 0.85, 0.3)
	for spoke_end in ends:
		canvas.draw_dashed_line(at, to_screen * spoke_end, Color(color, 0.7), 1.5, 6.0)
	canvas.draw_circle(at, 7.0, Color(0.05, 0.05, 0.08, 0.6))
	canvas.draw_arc(at, 7.0, 0.0, TAU, 20, color, 2.0, true)
	canvas.draw_line(at - Vector2(11, 0), at + Vector2(11, 0), color, 2.0)
	canvas.draw_line(at - Vector2(0, 11), at + Vector2(0, 11), color, 2.0)


## A dashed rectangle in screen pixels (a focused problem's area).
static func dashed_rect(canvas: Control, box: Rect2, color: Color) -> void:
	var corners := [box.position, Vector2(box.end.x, box.position.y), box.end]
	corners.append(Vector2(box.position.x, box.end.y))
	for i in 4:
		var a: Vector2 = corners[i]
		var b: Vector2 = corners[(i + 1) % 4]
		canvas.draw_dashed_line(a, b, color, 2.0, 8.0)
