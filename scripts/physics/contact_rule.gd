class_name ContactRule
extends RefCounted
## The one contact rule every contact asks (static shapes, a ball held by its supports, two
## balls): a contact bounces only when the ball comes in faster than the bounce threshold,
## not counting what gravity alone added to its approach in this step, so a resting ball
## settles instead of bouncing on the spot. Internal to scripts/physics.


## True when a contact whose normal speed is `vn` (negative: approaching) bounces;
## `gravity_n_dt` is gravity's share along the normal over the step (gravity · n · dt: its
## approach, when negative, is not counted), `threshold` the tuning's bounce_threshold.
static func bounces(vn: float, gravity_n_dt: float, threshold: float) -> bool:
	return minf(gravity_n_dt, 0.0) - vn > threshold
