class_name TuningPresets
extends RefCounted
## Each game's physics constants, converted from its seed: the presets a board starts from
## (BoardTextReader fills what a board file leaves out from them; BoardWorldFactory uses
## them for a level with no tuning). The physics layer itself knows no game.
##
## The Flash pachinko chapter counts in 30 ms ticks, the tilt maze in 16 ms frames: a
## constant of k px/tick becomes k / tick px/s, and k px/tick² becomes k / tick² px/s².

## Flash chapter: one tick is 30 ms.
const FLASH_TICK := 0.03
## Tilt maze tutorial: one animation frame is 16 ms (its main() divides by 16).
const MAZE_FRAME := 0.016


## The preset for a maze (`is_maze`) or a pachinko board.
static func for_kind(is_maze: bool) -> PhysicsTuning:
	return maze() if is_maze else pachinko()


## The Flash pachinko chapter's constants: gravity 0.7 px/tick², bounce 0.6, min horizontal
## speed 0.5 px/tick. Flash capped speed at 10 px/tick (333 px/s); our launch rail makes the
## ball ride the inside of the ring up and over, which needs sqrt(5·g·R) at the bottom
## (about 1,400 px/s for a 500 px ring), so the cap here is 1,600 px/s.
static func pachinko() -> PhysicsTuning:
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
## normal speed, no tangential loss. Gravity starts at zero: the tilt sets it. Physics of
## the usual kind: the total speed capped, friction against the velocity, caps rolled round.
static func maze() -> PhysicsTuning:
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


## The tilt maze exactly as the tutorial's JavaScript moves its balls (measured against it
## by tests/unit/test_physics_seed_reference.gd): maze() with the speed capped per axis
## (x before a frame's friction, y after, as the seed does),
## friction against the downhill direction, caps that glance (head-on stops dead), and two
## 8 ms steps per 16 ms frame. The classic maze uses it.
static func maze_seed() -> PhysicsTuning:
	var t := maze()
	t.speed_cap = PhysicsTuning.SpeedCap.PER_AXIS
	t.friction_against = PhysicsTuning.FrictionAgainst.GRAVITY
	t.wall_cap_contact = PhysicsTuning.CapContact.GLANCE
	t.x_cap_friction_time = MAZE_FRAME
	t.fixed_hz = 2.0 / MAZE_FRAME
	return t
