extends Node3D
## The 3D stage that gives the board true perspective, as the seed's CSS rotateX/rotateY
## with `perspective: 600px` did: a quad textured with the 2D board, on a tray with some
## depth, rotated by the tilt, seen by a perspective camera 600 seed pixels away.
## One 3D unit is 100 board pixels.

const Palette := preload("res://scenes/maze/maze_palette.gd")
const UNITS_PER_PX := 0.01
## The seed's CSS perspective distance, in board pixels.
const PERSPECTIVE_PX := 600.0
## Margin of the tray around the board, and its thickness, in board pixels.
const TRAY_MARGIN := 9.0
const TRAY_DEPTH := 14.0
## How far below the board the table (and the board's shadow) is, in board pixels.
const SHADOW_DROP_PX := 60.0
## Share of the screen height the board fills, and where its centre sits across the
## screen (-1 left edge, 1 right edge).
const HEIGHT_SHARE := 0.86
const CENTRE_ACROSS := -0.27

var _pivot := Node3D.new()
var _board := MeshInstance3D.new()
var _tray := MeshInstance3D.new()
var _camera := Camera3D.new()
var _shadow := MeshInstance3D.new()
var _board_size := Vector2(350.0, 315.0)


func _ready() -> void:
	var env := Environment.new()
	env.background_mode = Environment.BG_COLOR
	env.background_color = Palette.BACKGROUND
	env.ambient_light_source = Environment.AMBIENT_SOURCE_COLOR
	env.ambient_light_color = Color.WHITE
	env.ambient_light_energy = 0.55
	var world_env := WorldEnvironment.new()
	world_env.environment = env
	add_child(world_env)
	var sun := DirectionalLight3D.new()
	sun.rotation_degrees = Vector3(-35.0, -25.0, 0.0)
	sun.light_energy = 0.8
	add_child(sun)
	add_child(_camera)
	_camera.current = true
	add_child(_shadow)
	add_child(_pivot)
	_pivot.add_child(_tray)
	_pivot.add_child(_board)
	get_viewport().size_changed.connect(_frame)
	_frame()


## Shows `texture` (the 2D board, `board_size` board pixels) on the tilting quad.
func set_board(texture: Texture2D, board_size: Vector2) -> void:
	_board_size = board_size
	var quad := QuadMesh.new()
	quad.size = board_size * UNITS_PER_PX
	_board.mesh = quad
	var mat := StandardMaterial3D.new()
	mat.shading_mode = BaseMaterial3D.SHADING_MODE_UNSHADED
	mat.albedo_texture = texture
	mat.texture_filter = BaseMaterial3D.TEXTURE_FILTER_LINEAR
	_board.material_override = mat
	var box := BoxMesh.new()
	var margin := Vector2.ONE * TRAY_MARGIN * 2.0
	box.size = Vector3(
		(board_size.x + margin.x) * UNITS_PER_PX,
		(board_size.y + margin.y) * UNITS_PER_PX,
		TRAY_DEPTH * UNITS_PER_PX
	)
	_tray.mesh = box
	var tray_mat := StandardMaterial3D.new()
	tray_mat.albedo_color = Palette.WALL.lightened(0.12)
	tray_mat.roughness = 0.7
	_tray.material_override = tray_mat
	_tray.position = Vector3(0.0, 0.0, -TRAY_DEPTH * 0.5 * UNITS_PER_PX - 0.002)
	# A soft shadow on the table below the board: it stays put while the board tilts.
	var shadow_quad := QuadMesh.new()
	shadow_quad.size = Vector2(box.size.x, box.size.y) * 1.04
	_shadow.mesh = shadow_quad
	var shadow_mat := StandardMaterial3D.new()
	shadow_mat.shading_mode = BaseMaterial3D.SHADING_MODE_UNSHADED
	shadow_mat.transparency = BaseMaterial3D.TRANSPARENCY_ALPHA
	shadow_mat.albedo_color = Color(Palette.JOYSTICK, 0.13)
	_shadow.material_override = shadow_mat
	_frame()


## Rotates the board: +x tilt lowers the right edge (balls roll right), +y lowers the
## bottom edge (balls roll down the screen), as the seed's rotateY / rotateX.
func set_tilt(tilt_deg: Vector2) -> void:
	_pivot.rotation = Vector3(deg_to_rad(tilt_deg.y), deg_to_rad(tilt_deg.x), 0.0)


## The board's current rotation in degrees (x = tilt across, y = tilt down), for tests.
func shown_tilt() -> Vector2:
	return Vector2(rad_to_deg(_pivot.rotation.y), rad_to_deg(_pivot.rotation.x))


## The camera, for projecting board points to the screen.
func camera() -> Camera3D:
	return _camera


# Places the camera the seed's perspective distance away and picks the field of view so the
# board fills HEIGHT_SHARE of the screen, then slides the board left of the screen centre.
func _frame() -> void:
	var distance := PERSPECTIVE_PX * UNITS_PER_PX
	var half_height := _board_size.y * UNITS_PER_PX * 0.5 / HEIGHT_SHARE
	_camera.fov = rad_to_deg(2.0 * atan(half_height / distance))
	_camera.position = Vector3(0.0, 0.0, distance)
	var view := get_viewport().get_visible_rect().size if is_inside_tree() else Vector2(16, 9)
	var aspect := view.x / maxf(view.y, 1.0)
	_pivot.position = Vector3(CENTRE_ACROSS * half_height * aspect, 0.0, 0.0)
	_shadow.position = _pivot.position + Vector3(0.05, -0.07, -SHADOW_DROP_PX * UNITS_PER_PX)
