class_name MazeStage
extends Node3D
## The 3D stage of the tilt maze: the board built from the level (maze_board_3d.gd) and its
## balls (maze_balls_3d.gd) on a pivot that the tilt rotates, as the seed's CSS rotateX /
## rotateY with `perspective: 600px` did; a sun that stays put while the board tilts, so
## walls and balls cast moving shadows; and a table far enough below that no corner of the
## board ever reaches it, with the board's shadow on it. One 3D unit is 100 board pixels.
## The camera frames the board in the screen region the game leaves it (maze_framing.gd).

const UNITS_PER_PX := 0.01
## The seed's CSS perspective distance, in board pixels.
const PERSPECTIVE_PX := 600.0
## The table sits this far (board pixels) below the lowest point any tilt gives the board.
const TABLE_CLEARANCE_PX := 10.0
## Where the sun shines (x right, y up the screen, z out of the screen): from the upper
## left and in front, so shadows fall down and to the right as on a desk lamp's board.
const SUN_DIRECTION := Vector3(0.42, -0.5, -1.0)
## How fast the goal's light fades after a ball is counted in (its brightness per second).
const GOAL_GLOW_FADE := 1.6
## Light energies: the ambient fill and the sun that shades.
const AMBIENT_ENERGY := 0.28
const SUN_ENERGY := 0.42
## On software GL the 3D picture is drawn at this share of the window's resolution and
## scaled up smoothly (the 2D panel beside it stays sharp), without MSAA: on llvmpipe MSAA
## alone cost two thirds of every frame, and the pixels drawn set most of the rest (FXAA
## would smooth the edges, but the GL Compatibility renderer has none). A graphics card
## draws at full resolution with the project's MSAA. tools/maze_fps.sh measures the choices.
const SOFTWARE_GL_RENDER_SCALE := 0.5
## Words in the names of software GL drivers (RenderingServer.get_video_adapter_name()).
const SOFTWARE_GL_NAMES: Array[String] = ["llvmpipe", "softpipe", "swrast", "swiftshader"]
## The room the steel balls reflect (a panorama made here, seen only in the balls): its
## size in pixels.
const ROOM_SIZE := Vector2i(256, 128)

## The tutorial's flat colours and red balls instead of wood and steel (set before
## `set_level`).
var tutorial_look := false
## Low graphics (the player's setting, for machines that draw 3D on the CPU): no soft
## shadows, no wood grain, no table shadow, no reflections in the balls, and on software GL
## the 3D drawn at the window's own size (`use_render_settings`); tools/maze_fps.sh measures
## it beside the full look. Set with `set_look`.
var low_graphics := false

var _world_env := WorldEnvironment.new()
var _pivot := Node3D.new()
var _board: MazeBoard3d = MazeBoard3d.new()
var _balls: MazeBalls3d = MazeBalls3d.new()
var _camera := Camera3D.new()
var _sun := DirectionalLight3D.new()
var _table: MazeTableShadow = MazeTableShadow.new()
var _table_z := -1.0
var _board_size := Vector2(350.0, 315.0)
var _ball_radius := 5.0
var _framing := MazeFraming.new()
var _region := Rect2()
## How brightly the goal's dish glows now (0 to 1).
var _goal_glow := 0.0
# the room the steel balls reflect (the environment's sky while they reflect it)
var _room_sky: Sky


func _ready() -> void:
	_world_env.environment = _environment()
	add_child(_world_env)
	use_render_settings(get_viewport(), RenderingServer.get_video_adapter_name(), low_graphics)
	# One light, no shadow map: the floor's shader lays soft shadows cast along the same
	# direction (maze_board_3d.gd). A shadow map cost a third of each frame on software GL
	# (its own pass over the floor, and jagged edges on thin walls at any affordable size).
	_sun.transform = Transform3D(Basis.looking_at(SUN_DIRECTION.normalized(), Vector3.UP))
	_sun.light_energy = SUN_ENERGY
	_sun.shadow_enabled = false
	add_child(_sun)
	add_child(_camera)
	_camera.current = true
	_table.colour = MazePalette.JOYSTICK
	_table.visible = not low_graphics
	add_child(_table)
	add_child(_pivot)
	_pivot.add_child(_board)
	_pivot.add_child(_balls)
	get_viewport().size_changed.connect(_frame)
	_frame()


func _exit_tree() -> void:
	# the window goes on to other screens: give them back the project's settings
	use_render_settings(get_viewport(), "")


## Builds the board of `level` (holes shown when `hard`) and the look of its balls.
func set_level(level: BoardLevel, hard: bool) -> void:
	_board_size = level.size
	_ball_radius = level.ball_radius
	_board.tutorial_look = tutorial_look
	_board.low_graphics = low_graphics
	_board.build(level, hard)
	_balls.clear()
	_balls.hole_depth_px = _board.hole_depth_px()
	_balls.set_material(
		MazeBallMaterial.make(tutorial_look, low_graphics), MazeBallMaterial.rim(tutorial_look)
	)
	_frame()


## Switches Low graphics (`low_graphics`) and the tutorial look (`tutorial_look`), on a board
## already built or not: a change in Settings shows at once on the board in play.
func set_look(low: bool, tutorial: bool) -> void:
	low_graphics = low
	tutorial_look = tutorial
	_board.tutorial_look = tutorial
	_board.set_low_graphics(low)
	_balls.set_material(MazeBallMaterial.make(tutorial_look, low), MazeBallMaterial.rim(tutorial))
	_table.visible = not low
	if _world_env.environment != null:
		_world_env.environment.reflected_light_source = (
			Environment.REFLECTION_SOURCE_DISABLED if low else Environment.REFLECTION_SOURCE_SKY
		)
		# the room is seen only in the balls' reflections: without them the sky goes too (on
		# software GL it cost 3 to 4 ms a frame though nothing showed it; tools/maze_fps.sh)
		_world_env.environment.sky = null if low else _room_sky
	if is_inside_tree():
		use_render_settings(get_viewport(), RenderingServer.get_video_adapter_name(), low)


## Shows or hides the holes and forgets the balls (the world was rebuilt).
func set_hard_mode(hard: bool) -> void:
	_board.set_hard_mode(hard)
	_balls.clear()


## Puts `node` on the tilting board (it tilts with it), in the same mesh units as the balls.
func add_on_board(node: Node3D) -> void:
	_pivot.add_child(node)


## Marks the hole a ball fell into; -1 for none.
func set_lost_hole(index: int) -> void:
	_board.set_lost_hole(index)


## Moves, rolls and drops the balls to match `rules`' world (call every frame). The camera
## stays where it is: the whole board is always in view.
func sync_balls(rules: MazeRules, delta: float) -> void:
	_balls.sync(rules, delta)
	_board.set_ball_shadows(_balls.shadow_casters())
	if _goal_glow > 0.0:
		_goal_glow = maxf(0.0, _goal_glow - GOAL_GLOW_FADE * maxf(delta, 0.0))
		_board.set_goal_glow(_goal_glow)


## Lights the goal's dish at once (a ball was just counted in); it fades over a moment.
func light_goal() -> void:
	_goal_glow = 1.0
	_board.set_goal_glow(_goal_glow)


## How brightly the goal's dish glows now (0 plain to 1), for tests.
func goal_glow() -> float:
	return _goal_glow


## Frames the board inside `region` (screen pixels): the part of the window the game's
## panels leave free. An empty rectangle means the whole window.
func set_board_region(region: Rect2) -> void:
	_region = region
	_frame()


## How the board is framed now (its scale and where it is drawn), for tests.
func framing() -> MazeFraming:
	return _framing


## Rotates the board: +x tilt lowers the right edge (balls roll right), +y lowers the
## bottom edge (balls roll down the screen), as the seed's rotateY / rotateX.
func set_tilt(tilt_deg: Vector2) -> void:
	var turned := Vector3(deg_to_rad(tilt_deg.y), deg_to_rad(tilt_deg.x), 0.0)
	if turned != _pivot.rotation:
		_pivot.rotation = turned
		_cast_shadows()


## The board's current rotation in degrees (x = tilt across, y = tilt down), for tests.
func shown_tilt() -> Vector2:
	return Vector2(rad_to_deg(_pivot.rotation.y), rad_to_deg(_pivot.rotation.x))


## The camera, for projecting board points to the screen.
func camera() -> Camera3D:
	return _camera


## The 3D board (floor, walls, frame, holes), for tests.
func board() -> MazeBoard3d:
	return _board


## The 3D balls, for tests.
func balls() -> MazeBalls3d:
	return _balls


## The sun, for tests.
func sun() -> DirectionalLight3D:
	return _sun


## The table's shade under the board (hidden with Low graphics), for tests.
func table() -> Node3D:
	return _table


## The stage's environment (light, the room the balls reflect), for tests.
func environment() -> Environment:
	return _world_env.environment


## Height (stage z) of the table under the board.
func table_height() -> float:
	return _table_z


## The lowest point (stage z) of the board's body as it is tilted now.
func lowest_board_point() -> float:
	return _lowest_point(_pivot.transform)


## Sets how `view` draws 3D for the graphics adapter named `adapter_name`: scaled down and
## without MSAA on software GL (SOFTWARE_GL_RENDER_SCALE), the project's settings otherwise.
## With `low` graphics on software GL the 3D is drawn straight to the window, without
## MSAA: there a scaled picture's extra buffer and its smoothed copy to the window cost more
## than the pixels it saves once the floor is plain (tools/maze_fps.sh: 34 frames per CPU
## second at full size against 31 at half, the full look 24.5).
static func use_render_settings(view: Viewport, adapter_name: String, low := false) -> void:
	view.scaling_3d_mode = Viewport.SCALING_3D_MODE_BILINEAR
	if low and is_software_gl(adapter_name):
		view.msaa_3d = Viewport.MSAA_DISABLED
		view.scaling_3d_scale = 1.0
	elif is_software_gl(adapter_name):
		view.msaa_3d = Viewport.MSAA_DISABLED
		view.scaling_3d_scale = SOFTWARE_GL_RENDER_SCALE
	else:
		view.msaa_3d = ProjectSettings.get_setting("rendering/anti_aliasing/quality/msaa_3d")
		view.scaling_3d_scale = 1.0


## True when `adapter_name` is a software GL driver (drawing on the CPU).
static func is_software_gl(adapter_name: String) -> bool:
	var lower := adapter_name.to_lower()
	for word in SOFTWARE_GL_NAMES:
		if lower.contains(word):
			return true
	return false


func _environment() -> Environment:
	var env := Environment.new()
	env.background_mode = Environment.BG_COLOR
	env.background_color = MazePalette.BACKGROUND
	env.ambient_light_source = Environment.AMBIENT_SOURCE_COLOR
	env.ambient_light_color = Color.WHITE
	env.ambient_light_energy = AMBIENT_ENERGY
	env.ambient_light_sky_contribution = 0.0
	# The room round the table, seen only in the steel balls' reflections.
	var sky_material := PanoramaSkyMaterial.new()
	sky_material.panorama = ImageTexture.create_from_image(room_panorama(ROOM_SIZE))
	_room_sky = Sky.new()
	_room_sky.sky_material = sky_material
	_room_sky.radiance_size = Sky.RADIANCE_SIZE_64
	env.sky = null if low_graphics else _room_sky
	env.reflected_light_source = Environment.REFLECTION_SOURCE_SKY
	return env


## A room for the balls to reflect, as an equirectangular panorama `size` big: a pale
## ceiling with two long lamps, warm walls with three bright windows, a dark wooden floor.
## Made of rectangles and gradients only (no file, nothing copied).
static func room_panorama(size: Vector2i) -> Image:
	var image := Image.create(size.x, size.y, false, Image.FORMAT_RGB8)
	var ceiling := Color(0.86, 0.85, 0.82)
	var wall := Color(0.72, 0.62, 0.5)
	var floor_colour := Color(0.25, 0.17, 0.11)
	var window := Color(0.95, 0.97, 1.0)
	var lamp := Color(1.0, 0.98, 0.92)
	for y in size.y:
		var v := (float(y) + 0.5) / float(size.y)  # 0 straight up, 1 straight down
		for x in size.x:
			var u := (float(x) + 0.5) / float(size.x)
			var c := wall
			if v < 0.3:
				c = ceiling.lerp(wall, v / 0.3)
				# two lamps across the ceiling
				if absf(v - 0.12) < 0.03 and (absf(u - 0.2) < 0.12 or absf(u - 0.7) < 0.12):
					c = lamp
			elif v > 0.56:
				c = wall.darkened(0.3).lerp(floor_colour, minf((v - 0.56) / 0.1, 1.0))
			else:
				# three windows round the walls, with a bar across each
				var pane := fmod(u * 3.0, 1.0)
				if absf(pane - 0.5) < 0.16 and v > 0.34 and v < 0.52 and absf(v - 0.43) > 0.008:
					c = window
			image.set_pixel(x, y, c)
	return image


# The lowest z of the board's outer box under the pivot transform `pose`.
func _lowest_point(pose: Transform3D) -> float:
	var box := _board.outer_box()
	var lowest := INF
	for i in 8:
		lowest = minf(lowest, (pose * box.get_endpoint(i)).z)
	return lowest


# Places the camera the seed's perspective distance away and fits every corner of the board
# under any tilt into the board's region (MazeFraming), and puts the table under the lowest
# point any tilt can give the board.
# The board's outer corners (frame included) at each full tilt, in the stage's space.
func _tilted_corners() -> PackedVector3Array:
	var box := _board.outer_box()
	var points := PackedVector3Array()
	var m := deg_to_rad(TiltInput.MAX_TILT_DEG)
	for corner: Vector2 in [Vector2(m, m), Vector2(m, -m), Vector2(-m, m), Vector2(-m, -m)]:
		var pose := Transform3D(Basis.from_euler(Vector3(corner.y, corner.x, 0.0)), Vector3.ZERO)
		for i in 8:
			points.append(pose * box.get_endpoint(i))
	return points


func _frame() -> void:
	var distance := PERSPECTIVE_PX * UNITS_PER_PX
	var view := get_viewport().get_visible_rect().size if is_inside_tree() else Vector2(1280, 720)
	var region := _region if _region.has_area() else Rect2(Vector2.ZERO, view)
	var points := _tilted_corners()
	var lowest := 0.0
	for p in points:
		lowest = minf(lowest, p.z)
	_framing.distance = distance
	_framing.near = _camera.near
	_framing.board_aspect = _framing.aspect_of(points)
	_framing.fit(points, view, region, _ball_radius * 2.0 * UNITS_PER_PX)
	_pivot.position = Vector3.ZERO
	_camera.position = Vector3(0.0, 0.0, distance)
	_camera.projection = Camera3D.PROJECTION_FRUSTUM
	_camera.keep_aspect = Camera3D.KEEP_HEIGHT
	_camera.size = _framing.size
	_camera.frustum_offset = _framing.offset
	_table_z = lowest - TABLE_CLEARANCE_PX * UNITS_PER_PX
	_cast_shadows()


# The shadows on the board and the board's on the table, for the board where it is now.
func _cast_shadows() -> void:
	if is_inside_tree():
		_board.cast_shadows(global_transform.basis * SUN_DIRECTION)
	var box := _board.outer_box()
	var corners := PackedVector3Array()
	for i in 8:
		corners.append(_pivot.transform * box.get_endpoint(i))
	_table.cast(corners, SUN_DIRECTION.normalized(), _table_z)
