class_name MazeBalls3d
extends Node3D
## The maze's balls in 3D: one lit sphere per ball of the rules' world, resting on the floor
## and rolling (each frame's move turns it about up × move by |move| / radius, so a painted
## band on it shows the roll). A ball that fell into a hole slides to the hole's centre and
## sinks, shrinking into the dark. Their shadows are the floor's (`shadow_casters` says
## where the balls are). Reads the world each frame; never moves a ball.

## How long a ball takes to drop out of sight into a hole, in seconds.
const FALL_SECONDS := 0.45
## A fall advances at most this much per frame, so it shows in a dozen frames or more even
## when a slow machine draws few of them.
const FALL_MAX_STEP := 1.0 / 30.0
## Steps per half sphere of the ball mesh (smooth enough for a highlight at 1080p).
const SPHERE_RINGS := 16
const SPHERE_SEGMENTS := 32
## The rims' coarser sphere (only its outline shows).
const RIM_RINGS := 8
const RIM_SEGMENTS := 16

## The ball's surface; set before the first `sync` (or with `set_material` later).
var material: Material
## The dark rim round each ball (MazeBallMaterial.rim), or null for none.
var rim_material: Material
## How deep the holes are, in board pixels (how far a falling ball sinks).
var hole_depth_px := 12.0

var _board_size := Vector2(350.0, 315.0)
var _mesh := SphereMesh.new()
## The rims' sphere: only its outline shows, so a coarse one does (a quarter of the triangles).
var _rim_mesh := SphereMesh.new()
## ball id -> MeshInstance3D, and the board position each was last drawn at.
var _nodes: Dictionary[int, MeshInstance3D] = {}
var _last: Dictionary[int, Vector2] = {}
## Balls falling into a hole: node -> [start board position, hole centre, seconds so far].
var _falls: Dictionary[MeshInstance3D, Array] = {}


func _init() -> void:
	_mesh.rings = SPHERE_RINGS
	_mesh.radial_segments = SPHERE_SEGMENTS
	_rim_mesh.rings = RIM_RINGS
	_rim_mesh.radial_segments = RIM_SEGMENTS


## Gives every ball on the board, and every ball to come, the surface `surface` and the rim
## `rim` (null: none) (balls falling into a hole keep the darkening copy they have).
func set_material(surface: Material, rim: Material = null) -> void:
	material = surface
	rim_material = rim
	for node: MeshInstance3D in _nodes.values():
		node.material_override = surface
	for node: MeshInstance3D in _nodes.values() + _falls.keys():
		_set_rim(node)


## The rim drawn round the ball `node`, or null (for tests).
func rim_of(node: MeshInstance3D) -> MeshInstance3D:
	return node.get_node_or_null(^"Rim") as MeshInstance3D


## Removes every ball (a reset rebuilds the world with new ids).
func clear() -> void:
	for node: MeshInstance3D in _nodes.values():
		node.queue_free()
	for node: MeshInstance3D in _falls.keys():
		node.queue_free()
	_nodes.clear()
	_last.clear()
	_falls.clear()


## Follows `rules`' world: new balls appear, moved balls roll, a ball gone while the game
## is lost falls into `rules.lost_hole`; falls in progress advance by `delta` seconds.
func sync(rules: MazeRules, delta: float) -> void:
	if rules == null or rules.world == null:
		return
	_board_size = rules.level.size
	var radius := rules.level.ball_radius
	_mesh.radius = radius * MazeMeshes.UNITS_PER_PX
	_mesh.height = radius * 2.0 * MazeMeshes.UNITS_PER_PX
	_rim_mesh.radius = _mesh.radius
	_rim_mesh.height = _mesh.height
	var ids := rules.world.get_ids()
	var positions := rules.world.get_positions()
	var seen := {}
	for i in ids.size():
		var id := ids[i]
		seen[id] = true
		var node: MeshInstance3D = _nodes.get(id)
		if node == null:
			node = _new_ball()
			_nodes[id] = node
			_last[id] = positions[i]
		var move := positions[i] - _last[id]
		node.basis = roll(node.basis, Vector3(move.x, -move.y, 0.0), radius)
		node.position = MazeMeshes.to_local(_board_size, positions[i], radius)
		_last[id] = positions[i]
	for id: int in _nodes.keys():
		if not seen.has(id):
			_start_fall(id, rules)
	_advance_falls(delta, radius)


## How many balls are drawn (falling ones included), for tests.
func shown_count() -> int:
	return _nodes.size() + _falls.size()


## The drawn ball of world ball `id`, or null (for tests).
func node_for(id: int) -> MeshInstance3D:
	return _nodes.get(id)


## Every ball in sight as a shadow caster for the floor: board x, y, the height of its
## centre above the floor and its radius, in px (a sinking ball's height goes below zero).
func shadow_casters() -> PackedVector4Array:
	var casters := PackedVector4Array()
	for node: MeshInstance3D in _nodes.values() + _falls.keys():
		if node.visible:
			var at := node.position / MazeMeshes.UNITS_PER_PX
			var board := Vector2(at.x + _board_size.x * 0.5, _board_size.y * 0.5 - at.y)
			casters.append(
				Vector4(
					board.x, board.y, at.z, _mesh.radius / MazeMeshes.UNITS_PER_PX * node.scale.x
				)
			)
	return casters


## How many balls are falling into a hole now (or lie at the bottom of one).
func falling_count() -> int:
	return _falls.size()


## How far the furthest fall has gone, 0 (none or just begun) to 1 (out of sight).
func fall_progress() -> float:
	var furthest := 0.0
	for fall: Array in _falls.values():
		var seconds: float = fall[2]
		furthest = maxf(furthest, clampf(seconds / FALL_SECONDS, 0.0, 1.0))
	return furthest


## The orientation after rolling `move` (board pixels, in the floor's plane, mesh axes) on
## a ball of `radius` pixels: turned about up × move by |move| / radius radians.
static func roll(orientation: Basis, move: Vector3, radius: float) -> Basis:
	var distance := move.length()
	if distance < 0.0001 or radius <= 0.0:
		return orientation
	var axis := Vector3.BACK.cross(move / distance)
	return (Basis(axis, distance / radius) * orientation).orthonormalized()


## How far into its fall a ball is at `t` seconds: [share of the way to the hole's centre,
## depth sunk in board pixels, scale], for a hole `depth` deep and a ball of `radius`.
static func fall_pose(t: float, depth: float, radius: float) -> Vector3:
	var k := clampf(t / FALL_SECONDS, 0.0, 1.0)
	var slide := minf(k * 2.5, 1.0)
	var sink := (depth + radius) * k * k
	return Vector3(slide, sink, lerpf(1.0, 0.55, k))


func _new_ball() -> MeshInstance3D:
	var node := MeshInstance3D.new()
	node.mesh = _mesh
	node.material_override = material
	# a random start orientation, so the balls' bands do not all line up
	node.basis = Basis.from_euler(Vector3(randf(), randf(), randf()) * TAU)
	node.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
	add_child(node)
	_set_rim(node)
	return node


# Gives the ball `node` the rim `rim_material` (a child sphere grown by RIM_WIDTH), or none.
func _set_rim(node: MeshInstance3D) -> void:
	var rim := rim_of(node)
	if rim_material == null:
		if rim != null:
			rim.queue_free()
			node.remove_child(rim)
		return
	if rim == null:
		rim = MeshInstance3D.new()
		rim.name = "Rim"
		rim.mesh = _rim_mesh
		rim.scale = Vector3.ONE * (1.0 + MazeBallMaterial.RIM_WIDTH)
		rim.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
		node.add_child(rim)
	rim.material_override = rim_material


func _start_fall(id: int, rules: MazeRules) -> void:
	var node: MeshInstance3D = _nodes[id]
	var start: Vector2 = _last[id]
	_nodes.erase(id)
	_last.erase(id)
	var hole := rules.lost_hole
	if hole < 0 or hole >= rules.level.holes.size():
		node.queue_free()  # removed for another reason: nothing to show
		return
	_falls[node] = [start, rules.level.holes[hole], 0.0]
	# its own copy of the surface, so it can darken as it sinks out of the light
	node.material_override = node.material_override.duplicate()


func _advance_falls(delta: float, radius: float) -> void:
	for node: MeshInstance3D in _falls.keys():
		var fall: Array = _falls[node]
		var t: float = fall[2] + clampf(delta, 0.0, FALL_MAX_STEP)
		fall[2] = t
		var pose := fall_pose(t, hole_depth_px, radius)
		var start: Vector2 = fall[0]
		var hole: Vector2 = fall[1]
		var centre := start.lerp(hole, pose.x)
		node.position = MazeMeshes.to_local(_board_size, centre, radius - pose.y)
		node.scale = Vector3.ONE * pose.z
		var surface := node.material_override as BaseMaterial3D
		if surface != null:
			surface.albedo_color = Color.WHITE.lerp(
				Color(0.2, 0.2, 0.2), clampf(t / FALL_SECONDS, 0.0, 1.0)
			)
		if t >= FALL_SECONDS:
			node.visible = false
