class_name MazeLowMarks
extends RefCounted
## Low graphics' goal and holes as their own small mesh just above a plain floor. The full
## floor shader works out the goal's dish and every hole's rim for each pixel of the floor,
## most of the screen; on a machine that draws 3D on the CPU that was Low's largest cost left
## (tools/maze_fps.sh, "Low, no floor"). Here the floor is one colour and only the pixels of
## the goal and the holes are drawn: the same picture, its shading worked out once per
## vertex on the CPU (the colours in linear light, as the floor shader has them).

## How far above the floor the marks lie, in board pixels (clear of the floor's depth).
const LIFT_PX := 0.2
## Pieces round the goal's dish and round a hole.
const GOAL_SEGMENTS := 40
const HOLE_SEGMENTS := 16
## The dish's shading is worked out on these rings (share of the goal's radius).
const DISH_RINGS: Array[float] = [0.0, 0.35, 0.6, 0.8, 0.93, 1.0]
## A hole's worn rim fades out over this many pixels past its edge (the floor shader's).
const RIM_PX := 3.0
## The glow's colour (linear), as the floor shader mixes it in.
const GLOW := Color(1.0, 0.95, 0.7)

## The marks' look: the floor's colour `floor_linear` and the goal's and holes' paint, all
## linear. Set the fields, then call mesh().
var floor_linear := Color(0.8, 0.7, 0.5)
var goal_linear := Color(0.2, 0.2, 0.5)
var rim_linear := Color(0.1, 0.1, 0.1)
var lost_linear := Color(0.8, 0.02, 0.01)
## Where the light comes from across the board (board px directions, y down).
var goal_light := Vector2(-0.64, -0.77)
## The dark lip outside the goal's edge, px.
var goal_line := 2.0


## The mesh of the goal's dish and lip and, for each of `holes`, a black hole with its worn
## rim (red for `lost_hole`), on a board of `board_size`. Vertex colours carry the paint; the
## dish's vertices have alpha 1 (the glow lights only them).
func mesh(
	board_size: Vector2,
	goal_center: Vector2,
	goal_radius: float,
	holes: PackedVector2Array,
	hole_radius: float,
	lost_hole: int
) -> ArrayMesh:
	var st := SurfaceTool.new()
	st.begin(Mesh.PRIMITIVE_TRIANGLES)
	st.set_normal(Vector3.BACK)
	_goal(st, board_size, goal_center, goal_radius)
	for i in holes.size():
		_hole(st, board_size, holes[i], hole_radius, i == lost_hole)
	return st.commit()


## The shader the marks are drawn with: unshaded vertex colours, the dish brightened by
## `goal_glow` (0 to 1) as the full floor's is.
static func material() -> ShaderMaterial:
	var mat := ShaderMaterial.new()
	mat.shader = preload("res://scenes/maze/maze_marks_low.gdshader")
	return mat


func _goal(st: SurfaceTool, size: Vector2, centre: Vector2, radius: float) -> void:
	var rings: Array[PackedVector2Array] = []
	var colours: Array[PackedColorArray] = []
	for share in DISH_RINGS:
		var points := PackedVector2Array()
		var paint := PackedColorArray()
		for k in GOAL_SEGMENTS:
			var dir := Vector2.from_angle(TAU * k / GOAL_SEGMENTS)
			points.append(centre + dir * radius * share)
			paint.append(_dish(dir, share))
		rings.append(points)
		colours.append(paint)
	for r in rings.size() - 1:
		_band(st, size, rings[r], rings[r + 1], colours[r], colours[r + 1])
	# The lip: a dark band from the goal's edge out to goal_line past it (no glow).
	var lip := goal_linear * 0.45
	lip = floor_linear.lerp(lip, 0.9)
	lip.a = 0.0
	var inner := PackedVector2Array()
	var outer := PackedVector2Array()
	var lip_colours := PackedColorArray()
	for k in GOAL_SEGMENTS:
		var dir := Vector2.from_angle(TAU * k / GOAL_SEGMENTS)
		inner.append(centre + dir * radius)
		outer.append(centre + dir * (radius + goal_line))
		lip_colours.append(lip)
	_band(st, size, inner, outer, lip_colours, lip_colours)


# The dish's colour at direction `dir` from the goal's centre and `share` of its radius: the
# floor shader's bowl (tinted, deepest in the middle, the side facing the light brighter).
func _dish(dir: Vector2, share: float) -> Color:
	var facing := dir.dot(-goal_light) * share
	var tint := floor_linear.lerp(goal_linear, 0.5)
	var shade := 0.84 - 0.1 * (1.0 - share * share) + 0.3 * facing
	return Color(tint.r * shade, tint.g * shade, tint.b * shade, 1.0)


func _hole(st: SurfaceTool, size: Vector2, centre: Vector2, radius: float, lost: bool) -> void:
	var edge := PackedVector2Array()
	var out := PackedVector2Array()
	var black := PackedColorArray()
	var worn := PackedColorArray()
	var plain := PackedColorArray()
	# The floor shader's rim: 55 % of the rim colour at the edge fading over RIM_PX, or the
	# lost hole's red at full strength to 2 px out, fading by 4 px.
	var at_edge := (
		floor_linear.lerp(lost_linear, 1.0) if lost else floor_linear.lerp(rim_linear, 0.55)
	)
	var reach := 4.0 if lost else RIM_PX
	for k in HOLE_SEGMENTS:
		var dir := Vector2.from_angle(TAU * k / HOLE_SEGMENTS)
		edge.append(centre + dir * radius)
		out.append(centre + dir * (radius + reach))
		black.append(Color(0.02, 0.02, 0.02, 0.0))
		worn.append(Color(at_edge, 0.0))
		plain.append(Color(floor_linear, 0.0))
	var middle := PackedVector2Array()
	middle.resize(HOLE_SEGMENTS)
	middle.fill(centre)
	_band(st, size, middle, edge, black, black)
	_band(st, size, edge, out, worn, plain)


# Two triangles per piece between the rings `a` and `b` (the same number of points, in
# order round), with their colours; seen from above.
func _band(
	st: SurfaceTool,
	size: Vector2,
	a: PackedVector2Array,
	b: PackedVector2Array,
	colours_a: PackedColorArray,
	colours_b: PackedColorArray
) -> void:
	var n := a.size()
	for k in n:
		var j := (k + 1) % n
		var points: Array[Vector2] = [a[k], b[j], b[k], a[k], a[j], b[j]]
		var paint: Array[Color] = [
			colours_a[k], colours_b[j], colours_b[k], colours_a[k], colours_a[j], colours_b[j]
		]
		for c in points.size():
			st.set_color(paint[c])
			st.add_vertex(MazeMeshes.to_local(size, points[c], LIFT_PX))
