extends Node2D
## Draws a maze board in board pixels: floor, goal circle (dashed), black holes, walls with
## round caps, and every ball in one `_draw` batch. Lives in the SubViewport whose texture
## is the tilting quad; `scale` sets how many texture pixels a board pixel gets.

const Palette := preload("res://scenes/maze/maze_palette.gd")
const GOAL_LINE := 5.0
const GOAL_DASHES := 22

## The rules whose board and balls are drawn.
var rules: MazeRules


func _process(_delta: float) -> void:
	queue_redraw()


func _draw() -> void:
	if rules == null or rules.level == null:
		return
	var level := rules.level
	draw_rect(Rect2(Vector2.ZERO, level.size), Palette.BACKGROUND)
	_draw_goal(level)
	if rules.hard_mode:
		_draw_holes(level)
	_draw_walls(level)
	_draw_balls()


func _draw_goal(level: BoardLevel) -> void:
	# The seed's goal is a 65 px circle with a 5 px dashed border outside it.
	var radius := level.goal_radius + GOAL_LINE * 0.5
	var step := TAU / float(GOAL_DASHES)
	for i in GOAL_DASHES:
		var from := step * float(i)
		draw_arc(level.goal_center, radius, from, from + step * 0.55, 8, Palette.GOAL, GOAL_LINE)


func _draw_holes(level: BoardLevel) -> void:
	var r := level.hole_radius
	for i in level.holes.size():
		var c := level.holes[i]
		if i == rules.lost_hole:
			# The hole that took a ball: red, with a white cross so it reads without colour.
			draw_circle(c, r * 1.15, Palette.HOLE_LOST)
			var d := r * 0.5
			draw_line(c + Vector2(-d, -d), c + Vector2(d, d), Palette.MARK, 2.0)
			draw_line(c + Vector2(-d, d), c + Vector2(d, -d), Palette.MARK, 2.0)
		else:
			# Black disc with a grey rim ring: the shape says "hole" as well as the colour.
			draw_circle(c, r, Palette.HOLE)
			draw_arc(c, r * 0.62, 0.0, TAU, 20, Palette.HOLE_RIM, 1.2)


func _draw_walls(level: BoardLevel) -> void:
	var w := level.wall_width
	var walls := level.walls
	for i in range(0, walls.size() - 1, 2):
		var a := walls[i]
		var b := walls[i + 1]
		draw_line(a, b, Palette.WALL, w)
		draw_circle(a, w * 0.5, Palette.WALL)
		draw_circle(b, w * 0.5, Palette.WALL)


func _draw_balls() -> void:
	var r := rules.level.ball_radius
	var shine := Palette.BALL.lightened(0.45)
	var shade := Palette.BALL.darkened(0.25)
	for p in rules.ball_positions():
		draw_circle(p + Vector2(0.6, 0.9), r, shade)
		draw_circle(p, r * 0.92, Palette.BALL)
		draw_circle(p + Vector2(-r * 0.3, -r * 0.35), r * 0.32, shine)
