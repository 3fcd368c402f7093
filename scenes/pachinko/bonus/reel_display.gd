class_name ReelDisplay
extends Node2D
## The three digital reels on the board: a dark window with one rolling number per reel,
## the reels stopping one by one, "REACH" while the last reel decides a possible jackpot,
## and four lamps for the spins waiting. Before the first spin the reels show dashes. The
## window is a solid piece in the world (BonusGeometry.reel_frame), so balls go round it.

## Half the panel's size, board pixels.
const HALF := BonusGeometry.REEL_HALF
const SYMBOL_COLORS: Array[Color] = [
	Color("ff5a5a"),
	Color("5ab4ff"),
	Color("7dff7a"),
	Color("ffd84a"),
	Color("d78bff"),
	Color("ff9a3c"),
	Color("48f0e0"),
	Color("ffffff"),
	Color("ff7ad0")
]

var _machine: BonusMachine
var _clock := 0.0


## Where the reels sit on `level`: high in the middle of the field.
static func spot(level: BoardLevel) -> Vector2:
	return BonusGeometry.reel_spot(level)


## What a reel's face shows for `symbol` (ReelSet.shown_symbol): its number, or a dash
## before the first spin.
static func face_text(symbol: int) -> String:
	return "-" if symbol < 0 else str(symbol + 1)


## Shows `machine`'s reels on `level`.
func bind(level: BoardLevel, machine: BonusMachine) -> void:
	_machine = machine
	position = spot(level)
	visible = BonusGeometry.has_reels(level)
	set_process(visible)
	queue_redraw()


func _process(delta: float) -> void:
	_clock += delta
	queue_redraw()


func _draw() -> void:
	if _machine == null:
		return
	var reels := _machine.reels
	var panel := Rect2(-HALF, HALF * 2.0)
	var frame := panel.grow(BonusGeometry.REEL_FRAME_RADIUS)
	var gold := Color(0.85, 0.68, 0.25, 0.95)
	# The roof balls roll off (the same shape as the frame in the world).
	var roof := PackedVector2Array(
		[
			frame.position,
			Vector2(0.0, frame.position.y - BonusGeometry.REEL_ROOF),
			Vector2(frame.end.x, frame.position.y),
		]
	)
	draw_colored_polygon(roof, gold)
	draw_polyline(roof, gold.lightened(0.3), 2.0)
	draw_rect(frame, gold)
	draw_rect(panel, Color(0.04, 0.02, 0.08, 0.88))
	var font := ThemeDB.fallback_font
	var cell := HALF.x * 2.0 / ReelSet.REELS
	for reel in ReelSet.REELS:
		var box := Rect2(
			Vector2(-HALF.x + cell * reel + 2.0, -HALF.y + 2.0),
			Vector2(cell - 4.0, HALF.y * 2.0 - 4.0)
		)
		draw_rect(box, Color(0.12, 0.1, 0.2, 0.9))
		var symbol := reels.shown_symbol(reel)
		var color := (
			SYMBOL_COLORS[symbol % SYMBOL_COLORS.size()] if symbol >= 0 else Color(0.5, 0.5, 0.6)
		)
		var text := face_text(symbol)
		var size := 30
		var width := font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, size).x
		var base := Vector2(box.get_center().x - width * 0.5, box.get_center().y + 11.0)
		if reels.is_spinning(reel):
			# A rolling number: slid down with a trail, so it reads as motion.
			var slide := fmod(reels.elapsed * 14.0, 1.0) * 16.0 - 8.0
			draw_string(
				font,
				base + Vector2(0, slide - 14.0),
				text,
				HORIZONTAL_ALIGNMENT_LEFT,
				-1,
				size,
				Color(color, 0.25)
			)
			draw_string(
				font,
				base + Vector2(0, slide),
				text,
				HORIZONTAL_ALIGNMENT_LEFT,
				-1,
				size,
				Color(color, 0.8)
			)
		else:
			draw_string_outline(
				font, base, text, HORIZONTAL_ALIGNMENT_LEFT, -1, size, 3, Color(0, 0, 0)
			)
			draw_string(font, base, text, HORIZONTAL_ALIGNMENT_LEFT, -1, size, color)
	_draw_reach(reels, font)
	_draw_queue_lamps()


func _draw_reach(reels: ReelSet, font: Font) -> void:
	if not (reels.stopped == ReelSet.REELS - 1 and reels.is_reach()):
		return
	var blink := 0.5 + 0.5 * sin(_clock * 16.0)
	var text := "REACH!"
	var width := font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, 16).x
	var at := Vector2(-width * 0.5, -HALF.y - 8.0)
	draw_string_outline(font, at, text, HORIZONTAL_ALIGNMENT_LEFT, -1, 16, 4, Color(0, 0, 0))
	draw_string(
		font, at, text, HORIZONTAL_ALIGNMENT_LEFT, -1, 16, Color(1.0, 0.3 + 0.6 * blink, 0.2)
	)


func _draw_queue_lamps() -> void:
	for i in BonusMachine.MAX_QUEUED:
		var at := Vector2(-18.0 + i * 12.0, HALF.y + 9.0)
		var on := i < _machine.queued_spins()
		draw_circle(at, 4.0, Color(0, 0, 0, 0.7))
		draw_circle(at, 3.0, Color("ffd84a") if on else Color(0.3, 0.25, 0.2))
