extends Node3D
## The maze board in 3D, built from its level data: the floor (a quad whose shader paints
## the goal ring and cuts the holes), every wall raised as one mesh, the frame round the
## board, and in hard mode the holes as dark tubes under the floor. Lives under the stage's
## tilting pivot; the balls are a sibling (maze_balls_3d.gd). Heights are in board pixels.

const Palette := preload("res://scenes/maze/maze_palette.gd")
const Meshes := preload("res://scenes/maze/maze_meshes.gd")
const FLOOR_SHADER := preload("res://scenes/maze/maze_floor.gdshader")
## Walls stand this many ball radii above the floor (a Labyrinth wall is about a ball high).
const WALL_HEIGHT_PER_RADIUS := 2.4
## The frame is this much taller than the walls, and this wide, in board pixels.
const FRAME_EXTRA_HEIGHT := 3.0
const FRAME_MARGIN := 11.0
## How far the board's body reaches below the floor, in board pixels.
const BODY_DEPTH := 16.0
## How deep a hole is, in hole radii (the tube must fit inside the body).
const HOLE_DEPTH_PER_RADIUS := 1.3
## The floor shader's limit on holes; more are drawn without their cut-out.
const MAX_HOLES := 64
## The render layer of the floor alone: the sun's shadows are drawn on this layer only.
const SHADOW_RECEIVER_LAYER := 2

var _level: BoardLevel
var _floor := MeshInstance3D.new()
var _walls := MeshInstance3D.new()
var _frame := MeshInstance3D.new()
var _holes := MeshInstance3D.new()
var _floor_material := ShaderMaterial.new()


func _ready() -> void:
	_floor_material.shader = FLOOR_SHADER
	for piece: MeshInstance3D in [_floor, _walls, _frame, _holes]:
		add_child(piece)
	_floor.material_override = _floor_material
	_floor.layers = 1 | SHADOW_RECEIVER_LAYER
	_walls.material_override = _plain(Palette.WALL, 0.55, 0.0)
	_frame.material_override = _plain(Palette.WALL.lightened(0.1), 0.6, 0.0)


## Builds the board for `level`; holes only when `hard` (the seed shows them in hard mode).
func build(level: BoardLevel, hard: bool) -> void:
	_level = level
	var size := level.size
	var quad := QuadMesh.new()
	quad.size = size * Meshes.UNITS_PER_PX
	_floor.mesh = quad
	var wall_height := wall_height_px()
	_walls.mesh = Meshes.walls(size, level.walls, level.wall_width, wall_height)
	_frame.mesh = Meshes.frame(size, FRAME_MARGIN, wall_height + FRAME_EXTRA_HEIGHT, BODY_DEPTH)
	var m := _floor_material
	m.set_shader_parameter("floor_color", Palette.BACKGROUND)
	m.set_shader_parameter("goal_color", Palette.GOAL)
	m.set_shader_parameter("rim_color", Palette.HOLE_RIM.darkened(0.4))
	m.set_shader_parameter("lost_color", Palette.HOLE_LOST)
	m.set_shader_parameter("board_size", size)
	m.set_shader_parameter("goal_center", level.goal_center)
	m.set_shader_parameter("goal_radius", level.goal_radius)
	m.set_shader_parameter("hole_radius", level.hole_radius)
	set_hard_mode(hard)


## Shows or hides the holes.
func set_hard_mode(hard: bool) -> void:
	if _level == null:
		return
	var centres := _level.holes if hard else PackedVector2Array()
	if centres.size() > MAX_HOLES:
		push_warning("MazeBoard3D: only the first %d holes are cut into the floor" % MAX_HOLES)
		centres = centres.slice(0, MAX_HOLES)
	var padded := centres.duplicate()
	padded.resize(MAX_HOLES)
	_floor_material.set_shader_parameter("holes", padded)
	_floor_material.set_shader_parameter("hole_count", centres.size())
	var rim := Color(0.42, 0.4, 0.38)
	_holes.mesh = Meshes.holes(_level.size, centres, _level.hole_radius, hole_depth_px(), rim)
	if _holes.mesh != null:
		var tube := _plain(Color.WHITE, 0.9, 0.1)
		tube.vertex_color_use_as_albedo = true
		_holes.mesh.surface_set_material(0, tube)
		_holes.mesh.surface_set_material(1, _plain(Color(0.02, 0.02, 0.02), 1.0, 0.0))
	set_lost_hole(-1)


## Marks the hole a ball fell into (red rim); -1 for none.
func set_lost_hole(index: int) -> void:
	_floor_material.set_shader_parameter("lost_hole", index)


## How tall the walls stand, in board pixels.
func wall_height_px() -> float:
	var radius := _level.ball_radius if _level != null else 5.0
	return radius * WALL_HEIGHT_PER_RADIUS


## How deep the holes are, in board pixels.
func hole_depth_px() -> float:
	var radius := _level.hole_radius if _level != null else 9.0
	return minf(radius * HOLE_DEPTH_PER_RADIUS, BODY_DEPTH - 1.0)


## The board's outer box (frame and body) in this node's space, for framing and the table.
func outer_box() -> AABB:
	var size := _level.size if _level != null else Vector2(350.0, 315.0)
	var top := wall_height_px() + FRAME_EXTRA_HEIGHT
	var lo := Meshes.to_local(size, Vector2(-FRAME_MARGIN, size.y + FRAME_MARGIN), -BODY_DEPTH)
	var hi := Meshes.to_local(size, Vector2(size.x + FRAME_MARGIN, -FRAME_MARGIN), top)
	return AABB(lo, hi - lo)


## The mesh parts by name, for tests: "floor", "walls", "frame", "holes".
func part(part_name: String) -> MeshInstance3D:
	match part_name:
		"floor":
			return _floor
		"walls":
			return _walls
		"frame":
			return _frame
		"holes":
			return _holes
	return null


static func _plain(colour: Color, roughness: float, specular: float) -> StandardMaterial3D:
	var mat := StandardMaterial3D.new()
	mat.albedo_color = colour
	mat.roughness = roughness
	mat.metallic_specular = specular
	if specular <= 0.0:
		# flat matte faces light the same per vertex as per pixel, for a fraction of the cost
		mat.specular_mode = BaseMaterial3D.SPECULAR_DISABLED
		mat.shading_mode = BaseMaterial3D.SHADING_MODE_PER_VERTEX
	return mat
