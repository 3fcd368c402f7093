class_name MazeBoard3d
extends Node3D
## The maze board in 3D, built from its level data: the floor (a quad whose shader paints
## the goal ring and cuts the holes), every wall raised as one mesh, the frame round the
## board, and in hard mode the holes as dark tubes under the floor. The floor shader lays
## the walls', the frame's and the balls' soft shadows on it (maze_floor_shade.gdshaderinc,
## fed by maze_soft_shadows.gd). Lives under the stage's tilting pivot; the balls are a
## sibling (maze_balls_3d.gd). Heights are in board pixels.

const FLOOR_SHADER := preload("res://scenes/maze/maze_floor.gdshader")
## Low graphics' floor: unshaded, plain colour, goal and holes painted (no shadows, no discard).
const FLOOR_LOW_SHADER := preload("res://scenes/maze/maze_floor_low.gdshader")
const SOLID_SHADER := preload("res://scenes/maze/maze_wood_solid.gdshader")
## The wood-and-steel look: a pale maple floor in boards one cell wide, walnut walls with
## lighter routed tops, and a darker frame (the tutorial's look keeps its flat paint).
const MAPLE := Color("e2c9a0")
const MAPLE_GRAIN := Color("b08456")
const WALNUT_SIDE := Color("5a3b22")
const WALNUT_TOP := Color("8a6240")
const WALNUT_GRAIN := Color("2e1b0e")
const FRAME_SIDE := Color("4a2e19")
const FRAME_TOP := Color("7a5434")
## Walls stand this many ball radii above the floor (a Labyrinth wall is about a ball high).
const WALL_HEIGHT_PER_RADIUS := 2.4
## The frame is this much taller than the walls, and this wide, in board pixels.
const FRAME_EXTRA_HEIGHT := 3.0
const FRAME_MARGIN := 11.0
## How far the board's body reaches below the floor, in board pixels.
const BODY_DEPTH := 16.0
## The dark lip the floor draws just outside the goal's edge (px): the dish a player sees
## reaches this far past the goal's radius, and every shipped board keeps it clear of walls.
const GOAL_LIP_PX := 2.0
## How deep a hole is, in hole radii (the tube must fit inside the body).
const HOLE_DEPTH_PER_RADIUS := 1.3
## Low graphics draws each wall's end in this many pieces (square ends): the walls were its
## largest cost on software GL (tools/maze_fps.sh: 36 frames per CPU second with them, 53
## without), and most of their triangles were in the rounded ends.
const LOW_WALL_CAP_SEGMENTS := 1
## The floor shader's limit on holes; more are drawn without their cut-out.
const MAX_HOLES := 64
## Share of the light a full shadow takes from the floor.
const SHADOW_DARKNESS := 0.3
## The floor's albedo is raised by this: the seed's pale floor stays as bright as it was
## when a shadowed light's extra pass lit it (that pass was added after the conversion for
## the screen and brightened it far more than its energy said), while the walls and balls
## keep the light they had.
const FLOOR_GAIN := 1.22
## Low graphics' unshaded floor is its albedo times this: about the light the lit floor gets.
const LOW_FLOOR_LIGHT := 0.95

## The tutorial's flat colours instead of wood (set before `build`).
var tutorial_look := false
## Low graphics: the wood's grain and the soft shadows are left out (the floor and walls in
## their plain colours), for machines that draw 3D on the CPU. See `set_low_graphics`.
var low_graphics := false

var _level: BoardLevel
var _floor := MeshInstance3D.new()
var _walls := MeshInstance3D.new()
var _frame := MeshInstance3D.new()
var _holes := MeshInstance3D.new()
## Low graphics' goal and holes (MazeLowMarks): drawn only on Low, over a plain floor.
var _marks := MeshInstance3D.new()
var _marks_material := MazeLowMarks.material()
var _hole_centres := PackedVector2Array()
var _lost_hole := -1
var _arrows := MazeFloorArrows.new()
var _floor_material := ShaderMaterial.new()
var _wall_material := ShaderMaterial.new()
var _frame_material := ShaderMaterial.new()


func _ready() -> void:
	_floor_material.shader = FLOOR_SHADER
	_floor_material.set_shader_parameter("shadow_darkness", SHADOW_DARKNESS)
	for piece: MeshInstance3D in [_floor, _walls, _frame, _holes, _marks, _arrows]:
		piece.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
		add_child(piece)
	_marks.material_override = _marks_material
	_floor.material_override = _floor_material
	_wall_material.shader = SOLID_SHADER
	_frame_material.shader = SOLID_SHADER
	_walls.material_override = _wall_material
	_frame.material_override = _frame_material


## Builds the board for `level`; holes only when `hard` (the seed shows them in hard mode).
func build(level: BoardLevel, hard: bool) -> void:
	_level = level
	var size := level.size
	var quad := QuadMesh.new()
	quad.size = size * MazeMeshes.UNITS_PER_PX
	_floor.mesh = quad
	var wall_height := wall_height_px()
	_build_walls()
	_frame.mesh = MazeMeshes.frame(size, FRAME_MARGIN, wall_height + FRAME_EXTRA_HEIGHT, BODY_DEPTH)
	_set_paint(
		"wall_field", ImageTexture.create_from_image(MazeSoftShadows.wall_field(size, level.walls))
	)
	_set_paint("wall_field_range", MazeSoftShadows.FIELD_RANGE_PX)
	_set_paint("wall_half_width", level.wall_width * 0.5)
	_set_paint("wall_height", wall_height)
	_set_paint("frame_height", wall_height + FRAME_EXTRA_HEIGHT)
	set_ball_shadows(PackedVector4Array())
	_arrows.build(level)
	_paint_look()
	_set_paint("goal_color", MazePalette.GOAL)
	_set_paint("rim_color", MazePalette.HOLE_RIM.darkened(0.4))
	_set_paint("lost_color", MazePalette.HOLE_LOST)
	_set_paint("board_size", size)
	_set_paint("goal_center", level.goal_center)
	_set_paint("goal_radius", level.goal_radius)
	_set_paint("goal_line", GOAL_LIP_PX)
	_set_paint("hole_radius", level.hole_radius)
	set_hard_mode(hard)


## The floor, walls and frame in the chosen look (`tutorial_look`).
func _paint_look() -> void:
	var wood := not tutorial_look
	_set_paint("floor_color", MAPLE if wood else MazePalette.BACKGROUND)
	_set_paint("floor_gain", 1.0 if wood else FLOOR_GAIN)
	var grain := wood and not low_graphics
	_set_paint("grain_strength", 0.55 if grain else 0.0)
	_set_paint("shadows_on", not low_graphics)
	_floor_material.shader = FLOOR_LOW_SHADER if low_graphics else FLOOR_SHADER
	_set_paint("low_light", LOW_FLOOR_LIGHT)
	_set_paint("grain_color", MAPLE_GRAIN)
	_set_paint("plank_px", _level.path_width + _level.wall_width if _level != null else 35.0)
	var looks := [
		[_wall_material, WALNUT_SIDE, WALNUT_TOP, MazePalette.WALL, MazePalette.WALL],
		[
			_frame_material,
			FRAME_SIDE,
			FRAME_TOP,
			MazePalette.WALL.lightened(0.1),
			MazePalette.WALL.lightened(0.1)
		],
	]
	for look: Array in looks:
		var material: ShaderMaterial = look[0]
		material.set_shader_parameter("side_color", look[1] if wood else look[3])
		material.set_shader_parameter("cap_color", look[2] if wood else look[4])
		material.set_shader_parameter("grain_color", WALNUT_GRAIN)
		material.set_shader_parameter("grain_strength", 0.5 if grain else 0.0)


## Switches Low graphics on or off on a board already built (see `low_graphics`).
func set_low_graphics(low: bool) -> void:
	var changed := low != low_graphics
	low_graphics = low
	_paint_look()
	_build_marks()
	if changed and _level != null:
		_build_walls()


## The number of triangles the walls are drawn with now (for tests and tools/maze_fps.sh).
func wall_triangles() -> int:
	if _walls.mesh == null:
		return 0
	var mesh := _walls.mesh as ArrayMesh
	return floori(mesh.surface_get_array_index_len(0) / 3.0)


# The walls' mesh: rounded, chamfered ends, or on Low graphics square ones without the
# chamfer (LOW_WALL_CAP_SEGMENTS).
func _build_walls() -> void:
	var segments := LOW_WALL_CAP_SEGMENTS if low_graphics else MazeMeshes.CAP_SEGMENTS
	_walls.mesh = MazeMeshes.walls(
		_level.size, _level.walls, _level.wall_width, wall_height_px(), segments, not low_graphics
	)


## Lights the goal's dish: 0 plain, 1 brightest (the stage fades it after a ball is counted).
func set_goal_glow(glow: float) -> void:
	_set_paint("goal_glow", clampf(glow, 0.0, 1.0))
	_marks_material.set_shader_parameter("goal_glow", clampf(glow, 0.0, 1.0))


# Low graphics' goal and holes as their own mesh over the plain floor, in the floor's
# paint (the holes' tubes are left out: the marks paint them black); the full look paints
# them in its floor shader and shows the tubes.
func _build_marks() -> void:
	_marks.visible = low_graphics and _level != null
	_holes.visible = not low_graphics
	if not _marks.visible:
		return
	var marks := MazeLowMarks.new()
	var paint := _floor_material
	var light: float = paint.get_shader_parameter("floor_gain") * LOW_FLOOR_LIGHT
	var floor_colour: Color = paint.get_shader_parameter("floor_color")
	marks.floor_linear = floor_colour.srgb_to_linear() * light
	marks.floor_linear.a = 1.0
	var goal_colour: Color = paint.get_shader_parameter("goal_color")
	var rim_colour: Color = paint.get_shader_parameter("rim_color")
	var lost_colour: Color = paint.get_shader_parameter("lost_color")
	marks.goal_linear = goal_colour.srgb_to_linear()
	marks.rim_linear = rim_colour.srgb_to_linear()
	marks.lost_linear = lost_colour.srgb_to_linear()
	marks.goal_line = GOAL_LIP_PX
	_marks.mesh = marks.mesh(
		_level.size,
		_level.goal_center,
		_level.goal_radius,
		_hole_centres,
		_level.hole_radius,
		_lost_hole
	)


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
	_set_paint("holes", padded)
	_set_paint("hole_count", centres.size())
	_hole_centres = centres
	_lost_hole = -1
	var rim := Color(0.42, 0.4, 0.38)
	_holes.mesh = MazeMeshes.holes(_level.size, centres, _level.hole_radius, hole_depth_px(), rim)
	if _holes.mesh != null:
		var tube := _plain(Color.WHITE, 0.9, 0.1)
		tube.vertex_color_use_as_albedo = true
		_holes.mesh.surface_set_material(0, tube)
		_holes.mesh.surface_set_material(1, _plain(Color(0.02, 0.02, 0.02), 1.0, 0.0))
	_set_paint("lost_hole", -1)
	_build_marks()


## Marks the hole a ball fell into (red rim); -1 for none.
func set_lost_hole(index: int) -> void:
	_set_paint("lost_hole", index)
	if index != _lost_hole:
		_lost_hole = index
		_build_marks()


## The floor's material (it paints the floor and lays the shadows on it).
func floor_material() -> ShaderMaterial:
	return _floor_material


## Points the shadows along `sun_direction` (world space, the way the light travels) for
## the board where it is now; call after every move of the board.
func cast_shadows(sun_direction: Vector3) -> void:
	var in_board := global_transform.basis.inverse() * sun_direction.normalized()
	_set_paint("sun_step", MazeSoftShadows.sun_step(in_board))


## The balls that cast shadows now: board x, y, the centre's height above the floor and the
## radius, in px (MazeBalls3D.shadow_casters); at most SoftShadows.MAX_BALLS.
func set_ball_shadows(casters: PackedVector4Array) -> void:
	var count := mini(casters.size(), MazeSoftShadows.MAX_BALLS)
	var padded := casters.slice(0, count)
	padded.resize(MazeSoftShadows.MAX_BALLS)
	_set_paint("balls", padded)
	_set_paint("ball_count", count)


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
	var lo := MazeMeshes.to_local(size, Vector2(-FRAME_MARGIN, size.y + FRAME_MARGIN), -BODY_DEPTH)
	var hi := MazeMeshes.to_local(size, Vector2(size.x + FRAME_MARGIN, -FRAME_MARGIN), top)
	return AABB(lo, hi - lo)


## The mesh parts by name, for tests: "floor", "walls", "frame", "holes", "marks".
func part(part_name: String) -> MeshInstance3D:
	var parts := {
		"floor": _floor,
		"walls": _walls,
		"frame": _frame,
		"holes": _holes,
		"marks": _marks,
	}
	return parts.get(part_name)


# A uniform of the floor's shader.
func _set_paint(uniform: String, value: Variant) -> void:
	_floor_material.set_shader_parameter(uniform, value)


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
