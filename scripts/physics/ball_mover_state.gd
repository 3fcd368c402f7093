extends RefCounted
## What one motion-stage lane works with: the step's ball arrays, static geometry and
## constants, copied into members by begin(), plus the lane's event and path buffers and
## the ball being moved. BallMover (the motion itself) extends it. Internal to
## scripts/physics.
##
## Members rather than reads through the store and geometry objects: a member is one indexed
## read, a named read a hash lookup, and the motion stage reads them per substep.

const BallStore := preload("res://scripts/physics/ball_store.gd")
const StaticGeometry := preload("res://scripts/physics/static_geometry.gd")
const BallEvents := preload("res://scripts/physics/ball_events.gd")
const ContactId := preload("res://scripts/physics/contact_id.gd")
const Windmills := preload("res://scripts/physics/windmills.gd")
const BladeReach := preload("res://scripts/physics/blade_reach.gd")
const SpeedRules := preload("res://scripts/physics/speed_rules.gd")

## A substep moves at most this share of the thinnest (ball + feature) radius: a centre
## that enters a shape is then never past the shape's middle, so it leaves on its own side.
const TRAVEL_SHARE := 0.5

## This lane's events of the step, in order (see BallEvents), and its path points.
var events := PackedInt32Array()
var event_speed := PackedFloat32Array()
var trace_ball := PackedInt32Array()
var trace_pos := PackedVector2Array()
## This lane's pushes on free windmills, in ball order: wheel index and change of its
## angular speed (rad/s); the world adds them up after the step (Windmills.advance).
var wheel_push_index := PackedInt32Array()
var wheel_push := PackedFloat64Array()

# Many private fields below are read and written only by BallMover, which extends this
# file; Godot counts a private field's use in its own file only, and its warnings filled the
# Debugger on every play-test. The fields end where the functions begin.
@warning_ignore_start("unused_private_class_variable")

# The step's inputs, copied in by begin(): ball arrays (this lane writes its own slots
# only), static geometry (read only) and constants. Members rather than reads through the
# store and geometry objects: a member is one indexed read, a named read a hash lookup.
# The ball arrays are the BallFields.TABLE rows this class declares as `_name` (see
# _take_balls()).
var _pos := PackedVector2Array()
var _vel := PackedVector2Array()
var _radius := PackedFloat32Array()
var _push := PackedVector2Array()
var _ids := PackedInt32Array()
var _alive := PackedByteArray()
var _asleep := PackedByteArray()
var _rest := PackedFloat32Array()
var _contact_a := PackedInt32Array()
var _contact_b := PackedInt32Array()
var _support_static := PackedVector2Array()
var _support_static2 := PackedVector2Array()
var _support_ball := PackedVector2Array()
var _sleep_ball_normal := PackedVector2Array()
var _drain_hits := PackedInt32Array()
var _drain_time := PackedFloat32Array()
var _goal_mask := PackedInt32Array()
var _zone_mask := PackedInt32Array()
var _cell_keys := PackedInt64Array()
var _key_cell := PackedInt32Array()
## This step's sorted keys (BallStore.sorted_keys): read only.
var _sorted_keys := PackedInt64Array()
## The store itself, for the rarer per-ball work that reads it by name (BallSleep.sleep_if_settled).
var _store: BallStore
## 1 for each hit event kind (BallEvents.Kind.PIN_HIT, WALL_HIT, RING_HIT, BLADE_HIT) some signal
## handler listens to: the others are not queued (on a busy board most events are hits).
var _hits_heard := PackedByteArray([1, 1, 1, 1])
## False when the store's broad-phase keys are stale this step: then none are written.
var _keyed := true
var _g: StaticGeometry
var _zoned := true
## False on a board without pins (a maze): the mover then skips the pin test outright.
var _has_pins := true
var _pin_start := PackedInt32Array()
var _pin_items := PackedInt32Array()
var _pin_item_pos := PackedVector2Array()
var _pin_item_rad := PackedFloat32Array()
var _pin_captures := PackedByteArray()
var _pin_tag := PackedInt32Array()
var _pin_min_speed_x := PackedFloat64Array()
var _wall_start := PackedInt32Array()
# The capsule walls of each grid cell: entries _wall_start[c] .. _wall_start[c + 1] of the
# _wall_item_* lists (the wall's index, its end a, a to b, 1 / |ab|², radius); the walls'
# own a to b and 1 / |ab|² by wall index. Copied as members: the narrow phase reads them
# per substep, and a member is one indexed read where another object's field is a lookup.
var _has_walls := false
var _wall_items := PackedInt32Array()
var _wall_item_a := PackedVector2Array()
var _wall_item_ab := PackedVector2Array()
var _wall_item_inv := PackedFloat32Array()
var _wall_item_rad := PackedFloat32Array()
var _wall_ab := PackedVector2Array()
var _wall_inv_len2 := PackedFloat32Array()
var _has_ring := false
var _ring_center := Vector2.ZERO
var _ring_min_speed_x := 0.0
var _has_drain_arc := false
var _has_sensors := false
## True when the sensors are zones alone (no holes, no goals): the mover then looks for a
## zone edge crossed before it calls BallSensors.
var _zones_only := false
var _zone_pos := PackedVector2Array()
var _zone_rad := PackedFloat32Array()
## The windmills as this lane sees them (see BladeReach), and whether the ball being moved
## can reach one this step (then it substeps for the blades and never falls asleep).
var _blades := BladeReach.new()
var _near_wheel := false
## True on a board with windmills (the substep count then looks for them).
var _has_wheels := false
var _origin := Vector2.ZERO
var _inv_cell := 1.0
var _cols := 1
var _last_cell := Vector2i.ZERO
var _gravity := Vector2.ZERO
var _dt := 0.0
var _max_speed := 0.0
## This step's rolling friction and speed cap (applied once per moving ball).
var _speed := SpeedRules.new()
# Its numbers, as members (see SpeedRules: BallMover applies them per ball without a call).
var _fr_shift := Vector2.ZERO
var _fr_zero := Vector2.ZERO
var _cap_per_axis := false
var _cap_low := Vector2.ZERO
var _cap_high := Vector2.ZERO
var _cap2 := 0.0
var _caps_glance := false
var _pin_e := 0.0
var _wall_e := 0.0
var _keep_tangent := 1.0
var _threshold := 0.0
var _rest_speed2 := 0.0
## 0 while no ball may fall asleep (just after a wake-up).
var _sleep_time := 0.0
## A ball pushed apart by more than a resting ball moves in a step is still settling.
var _settled_push := 0.0
var _tracing := false
# The ball being moved: slot, position, velocity, radius, substep time, push per substep.
var _i := 0
var _p := Vector2.ZERO
var _v := Vector2.ZERO
var _r := -1.0
var _h := 0.0
var _push_step := Vector2.ZERO
# Contacts of last step (a persisting one slides) and of this one, with their normals.
var _held_a := ContactId.NONE
var _held_b := ContactId.NONE
var _cur_a := ContactId.NONE
var _cur_b := ContactId.NONE
var _n_a := Vector2.ZERO
var _n_b := Vector2.ZERO
## Set when the ball left the world this substep (captured by a pin or drained).
var _gone := false
## Where the ball being moved started this step (for the sensors' path test).
var _p_start := Vector2.ZERO
# Per-radius limits, cached while consecutive balls share a radius.
var _max_travel := 0.0
var _ring_lim := 0.0
var _ring_lim2 := 0.0

@warning_ignore_restore("unused_private_class_variable")


## Takes this step's state and constants and clears the lane's buffers. Called on the
## world's thread before the lanes run; `may_sleep` is false just after a wake-up;
## `hits_heard` has 1 for each hit event kind to queue (see _hits_heard).
func begin(
	b: BallStore,
	g: StaticGeometry,
	wheels: Windmills,
	t: PhysicsTuning,
	gravity: Vector2,
	friction: Vector2,
	dt: float,
	may_sleep: bool,
	hits_heard: PackedByteArray
) -> void:
	_hits_heard = hits_heard
	_take_balls(b)
	_take_geometry(g)
	_blades.take(wheels)
	_has_wheels = _blades.has_wheels
	_near_wheel = false
	_gravity = gravity
	_dt = dt
	_max_speed = t.max_speed
	_speed.prepare(t, gravity, friction.max(Vector2.ZERO) * dt, dt)
	_fr_shift = _speed.shift
	_fr_zero = _speed.toward_zero
	_cap_per_axis = _speed.per_axis
	_cap_low = _speed.low
	_cap_high = _speed.high
	_cap2 = _speed.cap * _speed.cap
	_caps_glance = t.wall_cap_contact == PhysicsTuning.CapContact.GLANCE
	_pin_e = t.restitution
	_wall_e = t.wall_restitution
	_keep_tangent = t.tangent_friction
	_threshold = t.bounce_threshold
	_rest_speed2 = t.rest_speed * t.rest_speed
	_sleep_time = t.sleep_time if may_sleep else 0.0
	_settled_push = t.rest_speed * dt
	_tracing = b.tracing
	_r = -1.0
	_cur_a = ContactId.NONE
	_cur_b = ContactId.NONE
	_n_a = Vector2.ZERO
	_n_b = Vector2.ZERO
	events.resize(0)
	event_speed.resize(0)
	trace_ball.resize(0)
	trace_pos.resize(0)
	wheel_push_index.resize(0)
	wheel_push.resize(0)


# BallFields.take(b, self) written out: a named set and get per row cost about 6 µs a
# step (in the editor, where the member names are made on each call, more), and each
# analysis world steps thousands of times. tests/unit/test_ball_fields.gd pins it to take().
func _take_balls(b: BallStore) -> void:
	_store = b
	_pos = b.pos
	_vel = b.vel
	_radius = b.radius
	_ids = b.ids
	_alive = b.alive
	_rest = b.rest
	_asleep = b.asleep
	_drain_hits = b.drain_hits
	_drain_time = b.drain_time
	_goal_mask = b.goal_mask
	_zone_mask = b.zone_mask
	_contact_a = b.contact_a
	_contact_b = b.contact_b
	_support_static = b.support_static
	_support_static2 = b.support_static2
	_support_ball = b.support_ball
	_sleep_ball_normal = b.sleep_ball_normal
	_push = b.push
	_cell_keys = b.cell_keys
	_key_cell = b.key_cell
	_keyed = b.keys_valid
	_sorted_keys = b.sorted_keys


func _take_geometry(g: StaticGeometry) -> void:
	_g = g
	_zoned = g.zoned
	_pin_start = g.pin_start
	_pin_items = g.pin_items if g.zoned else g.all_pins
	_pin_item_pos = g.pin_item_pos if g.zoned else g.pin_pos
	_pin_item_rad = g.pin_item_radius if g.zoned else g.pin_radius
	_pin_captures = g.pin_captures
	_pin_tag = g.pin_tag
	_pin_min_speed_x = g.pin_min_speed_x
	_has_pins = not _pin_items.is_empty()
	_has_walls = not g.wall_a.is_empty()
	_wall_start = g.wall_start
	_wall_items = g.wall_items
	_wall_item_a = g.wall_item_a
	_wall_item_ab = g.wall_item_ab
	_wall_item_inv = g.wall_item_inv
	_wall_item_rad = g.wall_item_radius
	_wall_ab = g.wall_ab
	_wall_inv_len2 = g.wall_inv_len2
	_has_ring = g.has_ring
	_ring_center = g.ring_center
	_ring_min_speed_x = g.ring_min_speed_x
	_has_drain_arc = g.has_drain_arc
	_has_sensors = not (g.hole_pos.is_empty() and g.goal_pos.is_empty() and g.zone_pos.is_empty())
	_zones_only = g.hole_pos.is_empty() and g.goal_pos.is_empty()
	_zone_pos = g.zone_pos
	_zone_rad = g.zone_radius
	_origin = g.origin
	_inv_cell = g.inv_cell
	_cols = g.cols
	_last_cell = Vector2i(g.cols - 1, g.rows - 1)


## The limits that depend on the ball radius (kept while consecutive balls share one).
func _set_radius(r: float) -> void:
	_r = r
	_max_travel = _g.max_travel(r, TRAVEL_SHARE)
	_ring_lim = maxf(_g.ring_radius - r, 0.0)
	_ring_lim2 = _ring_lim * _ring_lim


## Records where ball `i` is between two substeps (the swept check's path; see
## BallStore.tracing).
func _trace(i: int) -> void:
	trace_ball.append(i)
	trace_pos.append(_p)


## Queues an event of `kind` for the ball being moved (see BallEvents).
func _queue(kind: int, index: int, speed: float) -> void:
	events.append(kind)
	events.append(_ids[_i])
	events.append(index)
	event_speed.append(speed)
