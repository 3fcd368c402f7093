class_name PhysicsTuning
extends Resource
## Per-board physics constants in pixels and seconds, converted from the two seeds.
##
## The Flash pachinko chapter counts in 30 ms ticks, the tilt maze in ~16 ms frames:
## a constant of k px/tick becomes k / 0.03 px/s, and k px/tick² becomes k / 0.03² px/s².

## Flash chapter: one tick is 30 ms.
const FLASH_TICK := 0.03
## Tilt maze tutorial: one animation frame is ~16 ms.
const MAZE_FRAME := 0.016

## Gravity in px/s². The maze rules overwrite the world's copy every frame from the tilt.
@export var gravity: Vector2 = Vector2(0.0, 0.7 / (FLASH_TICK * FLASH_TICK))
## Kept fraction of the normal speed when a ball bounces off a pin or the ring.
@export_range(0.0, 1.0) var restitution: float = 0.6
## Kept fraction of the normal speed when a ball bounces off a capsule wall.
@export_range(0.0, 1.0) var wall_restitution: float = 0.6
## Kept fraction of the normal relative speed when two balls bounce.
@export_range(0.0, 1.0) var ball_restitution: float = 0.6
## Kept fraction (0..1) of the tangential speed on a bouncing contact. A ball sliding or
## rolling along a surface (a persisting contact) keeps its tangential speed: only
## `rolling_friction` slows it, so the launch rail pumps in no energy and drains none.
@export_range(0.0, 1.0) var tangent_friction: float = 0.6
## Rolling friction in px/s² on the maze floor, per axis; only slows, never reverses.
@export var rolling_friction: float = 0.0
## Gravity in px/s² of a board tilted 90°: a tilt θ gives `tilt_gravity · sin θ` per axis.
@export var tilt_gravity: float = 0.0
## Speed cap in px/s.
@export var max_speed: float = 1600.0
## After touching a pin, a ball's horizontal speed is at least this (px/s), so no ball
## balances on a pin top (Flash: 0.5 px/tick). A pin material: BoardWorldFactory gives it
## to each pin it adds; the world itself does not read it.
@export var min_horizontal_speed: float = 0.5 / FLASH_TICK
## Fixed simulation steps per second.
@export var fixed_hz: float = 120.0
## Normal approach speed (px/s) below which a new contact does not bounce: resting balls
## settle instead of buzzing. Hits below it emit no pin_hit / wall_hit / ring_hit either.
@export var bounce_threshold: float = 30.0
## Speed (px/s) below which a ball counts as resting (see BallWorld.get_ball_rest_time).
@export var rest_speed: float = 8.0
## Seconds a ball must rest (below `rest_speed`, no other ball pushing it) before it falls
## asleep: a sleeping ball is skipped until a ball hits it faster than `rest_speed`, a
## gravity change it cannot bear (its walls and friction no longer hold it), the ball under
## it leaves, or a ball is moved or removed. 0 turns sleeping off.
@export var sleep_time: float = 0.1
## Seconds of sliding ring contact inside the gutter arc that also drain a ball: a ball
## that rolls instead of bouncing must leave too.
@export var gutter_slide_time: float = 0.5


## The Flash pachinko chapter's constants: gravity 0.7 px/tick², bounce 0.6, min horizontal
## speed 0.5 px/tick. Flash capped speed at 10 px/tick (333 px/s); our launch rail makes the
## ball ride the inside of the ring up and over, which needs sqrt(5·g·R) at the bottom
## (about 1,400 px/s for a 500 px ring), so the cap here is 1,600 px/s.
static func pachinko_defaults() -> PhysicsTuning:
	var t := PhysicsTuning.new()
	t.gravity = Vector2(0.0, 0.7 / (FLASH_TICK * FLASH_TICK))
	t.restitution = 0.6
	t.wall_restitution = 0.6
	t.ball_restitution = 0.6
	t.tangent_friction = 0.6
	t.rolling_friction = 0.0
	t.tilt_gravity = 0.0
	t.max_speed = 1600.0
	t.min_horizontal_speed = 0.5 / FLASH_TICK
	t.fixed_hz = 120.0
	t.bounce_threshold = 30.0
	t.rest_speed = 8.0
	return t


## The tilt maze's constants: g = 2 px/frame² (7,812.5 px/s² at 90°), friction μ = 0.01
## (so μ·g = 78.125 px/s²), max speed 1.5 px/frame (93.75 px/s), walls keep 1/3 of the
## normal speed, no tangential loss. Gravity starts at zero: the tilt sets it.
static func maze_defaults() -> PhysicsTuning:
	var t := PhysicsTuning.new()
	t.tilt_gravity = 2.0 / (MAZE_FRAME * MAZE_FRAME)
	t.gravity = Vector2.ZERO
	t.restitution = 1.0 / 3.0
	t.wall_restitution = 1.0 / 3.0
	t.ball_restitution = 1.0 / 3.0
	t.tangent_friction = 1.0
	t.rolling_friction = 0.01 * t.tilt_gravity
	t.max_speed = 1.5 / MAZE_FRAME
	t.min_horizontal_speed = 0.0
	t.fixed_hz = 120.0
	t.bounce_threshold = 10.0
	t.rest_speed = 2.0
	return t
