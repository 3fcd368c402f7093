class_name MazeGhost3d
extends Node3D
## The ghost of the best run in the 3D maze: translucent balls standing where the best run's
## balls were at the same step. It lives on the tilting board (the stage's `add_on_board`),
## so it tilts with it; it casts no shadow and takes no light of its own: a see-through blue
## glass ball with a firm blue outline (maze_ghost.gdshader), so it reads as "not a real
## ball" beside the solid steel ones. Call `show_balls` every frame and `clear` on a reset.

const GHOST_SHADER := preload("res://scenes/maze/maze_ghost.gdshader")
## How much of the ghost's body hides what is behind it (its rim and highlight show more).
const OPACITY := 0.22

## Ghost ball positions last shown, in board pixels (read by tests).
var shown_positions := PackedVector2Array()

var _board_size := Vector2(350.0, 315.0)
var _mesh := SphereMesh.new()
var _material := ShaderMaterial.new()
var _nodes: Array[MeshInstance3D] = []


func _init() -> void:
	# round enough that its outline is a circle at the size balls are drawn
	_mesh.rings = 12
	_mesh.radial_segments = 24
	_material.shader = GHOST_SHADER
	_material.set_shader_parameter("opacity", OPACITY)


## The best run's ghost to race on `level` in a mode, or null: the setting is off, or there
## is no best time yet. A replay file without a best time (left from an earlier save) is not a
## best run: trial 7 saw it stand still on the start spot of a first try that said "Best --".
static func best_run(level: BoardLevel, hard: bool) -> GhostRun:
	if not App.settings.show_ghost or App.best_maze_time(level.board_id, hard) < 0.0:
		return null
	return GhostRun.load_best(level, hard)


## Sets the board size (pixels) that positions are measured on.
func set_board_size(board_size: Vector2) -> void:
	_board_size = board_size


## Shows ghost balls at `positions` (board pixels) with `radius` pixels.
func show_balls(positions: PackedVector2Array, radius: float) -> void:
	shown_positions = positions
	_mesh.radius = radius * MazeMeshes.UNITS_PER_PX
	_mesh.height = radius * 2.0 * MazeMeshes.UNITS_PER_PX
	while _nodes.size() < positions.size():
		var node := MeshInstance3D.new()
		node.mesh = _mesh
		node.material_override = _material
		node.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
		add_child(node)
		_nodes.append(node)
	for i in _nodes.size():
		var node := _nodes[i]
		node.visible = i < positions.size()
		if node.visible:
			node.position = MazeMeshes.to_local(_board_size, positions[i], radius)


## Hides the ghost.
func clear() -> void:
	shown_positions = PackedVector2Array()
	for node in _nodes:
		node.visible = false
