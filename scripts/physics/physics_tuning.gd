class_name PhysicsTuning
extends Resource
## Per-board physics constants and material options, in pixels and seconds. The games'
## presets (converted from the two seeds) are in TuningPresets; these field defaults are the
## pachinko preset's.

## What max_speed limits (see speed_cap).
enum SpeedCap { TOTAL, PER_AXIS }
## What rolling friction pushes against (see friction_against).
enum FrictionAgainst { VELOCITY, GRAVITY }
## How a ball answers a wall cap (see wall_cap_contact).
enum CapContact { ROLL_ROUND, GLANCE }

## Flash chapter: one tick is 30 ms.
const FLASH_TICK := 0.03

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
## What max_speed caps: the speed (TOTAL) or each axis on its own (PER_AXIS, as the tilt
## maze seed does: a diagonal then rolls up to √2 times faster than a straight run).
@export var speed_cap: SpeedCap = SpeedCap.TOTAL
## Seconds of rolling friction the x axis still loses after its speed cap while gravity pulls
## along x (PER_AXIS only). The tilt maze seed caps x before it takes a frame's friction and
## y after, so its x tops out at 1.5 − 0.02 = 1.48 px a frame and y at 1.5: one seed frame
## (0.016) on the classic maze. That small asymmetry is what slides a ball off a wall cap it
## meets dead on along the diagonal; 0 caps both axes alike.
@export var x_cap_friction_time: float = 0.0
## What rolling friction opposes, per axis: the ball's velocity (VELOCITY), or the downhill
## direction of gravity (GRAVITY, as the tilt maze seed does: it only lowers the downhill
## pull, to zero at most; an axis with no gravity slows as with VELOCITY).
@export var friction_against: FrictionAgainst = FrictionAgainst.VELOCITY
## How a ball answers a wall's round cap: like any round surface (ROLL_ROUND: bounces with
## wall_restitution, then rolls round the curve), or GLANCE, as the tilt maze seed's
## rollAroundCap: only the speed along the cap's tangent is kept, so a head-on hit stops
## dead and a glancing one goes on along the tangent, leaving the cap (moved on by its kept
## speed once more each step, as the seed moves it twice a frame).
@export var wall_cap_contact: CapContact = CapContact.ROLL_ROUND
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
## Seconds of sliding ring contact inside the drain arc that also drain a ball: a ball
## that rolls instead of bouncing must leave too.
@export var drain_slide_time: float = 0.5
