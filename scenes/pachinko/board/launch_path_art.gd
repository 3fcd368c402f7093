class_name LaunchPathArt
extends "res://scenes/pachinko/board/board_layer.gd"
## The launch path: the channel between the ring and the chrome guide rail that a fired
## ball rides up into the field, with the stopper at its bottom.

const CHANNEL := Color(0.02, 0.01, 0.06, 0.55)
const RAIL := Color("d7dbe6")
const RAIL_SHADE := Color("5d6075")


func _draw() -> void:
	if _level == null or _level.rail_width <= 0.0:
		return
	var c := _level.ring_center
	var from := deg_to_rad(minf(_level.rail_start_deg, _level.rail_end_deg))
	var to := deg_to_rad(maxf(_level.rail_start_deg, _level.rail_end_deg))
	var mid := _level.ring_radius - _level.rail_width * 0.5
	draw_arc(c, mid, from, to, 96, CHANNEL, _level.rail_width, true)
	var guide := LaunchRail.guide_points(_level)
	var width := LaunchRail.GUIDE_WALL_RADIUS * 2.0
	draw_polyline(guide, RAIL_SHADE, width + 2.5, true)
	draw_polyline(guide, RAIL, width, true)
	var stopper := LaunchRail.stopper(_level)
	draw_line(stopper[0], stopper[1], RAIL_SHADE, width + 3.0, true)
	draw_line(stopper[0], stopper[1], Color("f0c24a"), width, true)
	# The deflector past the rail's end is a real wall: a ball must see what bounces it.
	var deflector := LaunchRail.deflector(_level)
	draw_line(deflector[0], deflector[1], RAIL_SHADE, width + 2.5, true)
	draw_line(deflector[0], deflector[1], RAIL, width, true)
	draw_circle(deflector[1], width * 0.5, RAIL, true, -1.0, true)
	# Arrow marks along the channel show which way a ball travels.
	var marks := 5
	for i in marks:
		var t := (float(i) + 0.5) / float(marks)
		var deg := lerpf(_level.rail_start_deg, _level.rail_end_deg, t)
		var a := deg_to_rad(deg)
		var p := c + Vector2(cos(a), sin(a)) * mid
		var up := -1.0 if _level.rail_end_deg < _level.rail_start_deg else 1.0
		var along := Vector2(-sin(a), cos(a)) * up
		var side := Vector2(cos(a), sin(a))
		var tip := p + along * 5.0
		var arrow := PackedVector2Array(
			[tip, p - along * 3.0 + side * 3.5, p - along * 3.0 - side * 3.5]
		)
		draw_colored_polygon(arrow, Color(1, 1, 1, 0.18))
