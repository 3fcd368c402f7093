extends RefCounted
## A bench scene built on Godot's own GodotPhysics2D through PhysicsServer2D: balls are
## rigid circles, pins and walls are shapes of one static body, the ring is a closed
## segment polygon. The engine steps it in its own physics frames; this object only builds,
## reads back positions and teleports balls for the harness.

const RING_SEGMENTS := 256

var space := RID()
var balls: Array[RID] = []

var _static_body := RID()
## Server-side shapes, not Shape2D resources: a resource frees its shape whenever it is
## released, and freeing a shape still on a ball with a NaN position hangs (see free_all).
var _shapes: Array[RID] = []


## Builds the scene; `ccd` turns on continuous collision for the balls (the fast scene).
## In the maze no ball may sleep: GodotPhysics2D does not wake a sleeping body when the
## space's gravity turns, so under the swinging tilt its sleepers would lie still against a
## reversed slope (measured: 442 of 1,000 asleep at step 300, when the tilt had reversed).
## BallWorld wakes every ball on a gravity change; this keeps both sides simulating the same.
func build(scene: Dictionary, gravity: Vector2, bounce: float, ccd: bool) -> void:
	var ps := PhysicsServer2D
	space = ps.space_create()
	ps.space_set_active(space, true)
	set_gravity(gravity)
	_static_body = ps.body_create()
	ps.body_set_mode(_static_body, PhysicsServer2D.BODY_MODE_STATIC)
	ps.body_set_space(_static_body, space)
	ps.body_set_param(_static_body, PhysicsServer2D.BODY_PARAM_BOUNCE, 0.0)
	ps.body_set_param(_static_body, PhysicsServer2D.BODY_PARAM_FRICTION, 0.0)
	var pin := ps.circle_shape_create()
	ps.shape_set_data(pin, scene["pin_r"])
	_shapes.append(pin)
	for p: Vector2 in scene["pins"]:
		ps.body_add_shape(_static_body, pin, Transform2D(0.0, p))
	var walls: PackedVector2Array = scene["walls"]
	var wall_r: float = scene["wall_r"]
	for k: int in walls.size() / 2:
		var a: Vector2 = walls[2 * k]
		var b: Vector2 = walls[2 * k + 1]
		var cap := ps.capsule_shape_create()
		# (radius, height), as CapsuleShape2D passes it; the height includes both caps.
		ps.shape_set_data(cap, Vector2(wall_r, a.distance_to(b) + 2.0 * wall_r))
		_shapes.append(cap)
		# A capsule's axis is its local y: turn it onto a→b.
		var angle: float = (b - a).angle() - PI / 2.0
		ps.body_add_shape(_static_body, cap, Transform2D(angle, (a + b) * 0.5))
	if scene["ring"]:
		var ring := ps.concave_polygon_shape_create()
		var segs := PackedVector2Array()
		for k: int in RING_SEGMENTS:
			segs.append(Vector2.from_angle(TAU * k / RING_SEGMENTS) * 500.0)
			segs.append(Vector2.from_angle(TAU * (k + 1) / RING_SEGMENTS) * 500.0)
		ps.shape_set_data(ring, segs)
		_shapes.append(ring)
		ps.body_add_shape(_static_body, ring)
	var ball_shape := ps.circle_shape_create()
	ps.shape_set_data(ball_shape, scene["ball_r"])
	_shapes.append(ball_shape)
	var pos: PackedVector2Array = scene["pos"]
	var vel: PackedVector2Array = scene["vel"]
	for i: int in pos.size():
		var body := ps.body_create()
		ps.body_set_mode(body, PhysicsServer2D.BODY_MODE_RIGID)
		ps.body_add_shape(body, ball_shape)
		ps.body_set_space(body, space)
		ps.body_set_param(body, PhysicsServer2D.BODY_PARAM_BOUNCE, bounce)
		ps.body_set_param(body, PhysicsServer2D.BODY_PARAM_FRICTION, 0.0)
		ps.body_set_param(body, PhysicsServer2D.BODY_PARAM_MASS, 1.0)
		if scene["mode"] == "maze":
			ps.body_set_state(body, PhysicsServer2D.BODY_STATE_CAN_SLEEP, false)
		if ccd:
			ps.body_set_continuous_collision_detection_mode(
				body, PhysicsServer2D.CCD_MODE_CAST_SHAPE
			)
		ps.body_set_state(body, PhysicsServer2D.BODY_STATE_TRANSFORM, Transform2D(0.0, pos[i]))
		ps.body_set_state(body, PhysicsServer2D.BODY_STATE_LINEAR_VELOCITY, vel[i])
		balls.append(body)


## Gravity of the whole space, as a strength and a direction.
func set_gravity(g: Vector2) -> void:
	var len: float = g.length()
	PhysicsServer2D.area_set_param(space, PhysicsServer2D.AREA_PARAM_GRAVITY, len)
	var dir: Vector2 = g / len if len > 0.0 else Vector2.DOWN
	PhysicsServer2D.area_set_param(space, PhysicsServer2D.AREA_PARAM_GRAVITY_VECTOR, dir)


## Maze tilt in degrees → gravity, as MazeTilt maps it for BallWorld.
func tilt(deg: Vector2) -> void:
	set_gravity(MazeTilt.gravity(deg, TuningPresets.maze().tilt_gravity))


## Every ball's centre, in spawn order (the order of the scene's `pos`).
func positions() -> PackedVector2Array:
	var out := PackedVector2Array()
	out.resize(balls.size())
	for i: int in balls.size():
		var t: Transform2D = PhysicsServer2D.body_get_state(
			balls[i], PhysicsServer2D.BODY_STATE_TRANSFORM
		)
		out[i] = t.origin
	return out


## Ball `i`'s linear velocity.
func velocity(i: int) -> Vector2:
	return PhysicsServer2D.body_get_state(balls[i], PhysicsServer2D.BODY_STATE_LINEAR_VELOCITY)


## Moves ball `i` to `p` with velocity `v` (the harness's respawns and relaunches).
func teleport(i: int, p: Vector2, v: Vector2) -> void:
	PhysicsServer2D.body_set_state(
		balls[i], PhysicsServer2D.BODY_STATE_TRANSFORM, Transform2D(0.0, p)
	)
	PhysicsServer2D.body_set_state(balls[i], PhysicsServer2D.BODY_STATE_LINEAR_VELOCITY, v)


## Frees every body, the space and the shapes, and returns true; the engine stops stepping
## this scene either way. GodotPhysics2D hangs taking a ball whose position went NaN out of
## its broadphase (S3's cast-shape CCD does this to most balls within a few steps), so such a
## scene is only switched off and left allocated until the process exits: returns false.
func free_all() -> bool:
	for p: Vector2 in positions():
		if not p.is_finite():
			PhysicsServer2D.space_set_active(space, false)
			balls.clear()
			_shapes.clear()
			return false
	for b: RID in balls:
		PhysicsServer2D.free_rid(b)
	balls.clear()
	if _static_body.is_valid():
		PhysicsServer2D.free_rid(_static_body)
	if space.is_valid():
		PhysicsServer2D.free_rid(space)
	for s: RID in _shapes:
		PhysicsServer2D.free_rid(s)
	_shapes.clear()
	return true
