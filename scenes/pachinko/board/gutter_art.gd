class_name GutterArt
extends "res://scenes/pachinko/board/board_layer.gd"
## The gutter: the dark slot at the bottom of the ring that swallows balls after their
## bounces there. It flashes when it takes a ball.

const SLOT := Color("07040d")

## Draw only the flash (the overlay above the baked board); otherwise only the slot.
@export var flash_only := false

var _flash := 0.0


## Lights the gutter briefly (a ball was drained).
func flash() -> void:
	_flash = 1.0
	set_process(true)


func _ready() -> void:
	set_process(false)


func _process(delta: float) -> void:
	_flash = maxf(_flash - delta * 2.5, 0.0)
	queue_redraw()
	if _flash <= 0.0:
		set_process(false)


func _draw() -> void:
	if _level == null or _level.gutter_end_deg <= _level.gutter_start_deg:
		return
	var c := _level.ring_center
	var r := _level.ring_radius
	var from := deg_to_rad(_level.gutter_start_deg)
	var to := deg_to_rad(_level.gutter_end_deg)
	if flash_only:
		if _flash > 0.0:
			draw_arc(c, r + 2.0, from, to, 32, Color(1.0, 0.35, 0.2, 0.75 * _flash), 6.0, true)
		return
	# A dark wedge of field just above the slot, fading inwards.
	for i in 5:
		var depth := 10.0 + 9.0 * i
		draw_arc(c, r - depth * 0.5, from, to, 32, Color(0, 0, 0, 0.13), depth, true)
	# The slot itself cuts through the ring band.
	draw_arc(c, r + 11.0, from, to, 32, SLOT, 26.0, true)
	# Grille bars across the slot so it reads as an opening, not a stain.
	var bars := 7
	for i in bars + 1:
		var a := lerpf(from, to, float(i) / float(bars))
		var u := Vector2(cos(a), sin(a))
		draw_line(c + u * (r - 1.0), c + u * (r + 22.0), Color("3a3350"), 2.0, true)
