class_name MazeHaptics
extends RefCounted
## Touch feedback for the maze: a gamepad rumble and a phone buzz when a ball knocks a wall
## (stronger for harder knocks) and a long one when a ball drops into a hole. Off when the
## player's "Vibration" setting is off. Knocks closer together than `MIN_GAP_MS` merge into
## one, so a ball rattling along a wall does not buzz continuously.

## Knocks softer than this (px/s) are not felt; at `HARD_KNOCK` the buzz is strongest.
const SOFT_KNOCK := 25.0
const HARD_KNOCK := 110.0
const MIN_GAP_MS := 70
## Buzz lengths in seconds: a knock at its softest and hardest, and a drop into a hole.
const KNOCK_SHORTEST := 0.03
const KNOCK_LONGEST := 0.09
const DROP_SECONDS := 0.35

## False turns every buzz off (the settings' "Vibration").
var enabled := true
## Where a buzz goes: called with (weak 0..1, strong 0..1, seconds). By default the
## gamepads and the phone; tests put a recorder here.
var output: Callable = send_to_devices

var _last_ms := -1000000


## A ball knocked a wall at `speed` px/s; `now_ms` lets tests drive the clock. True when
## it buzzed.
func knock(speed: float, now_ms: int = -1) -> bool:
	if not enabled or not is_finite(speed) or speed < SOFT_KNOCK:
		return false
	var now := Time.get_ticks_msec() if now_ms < 0 else now_ms
	if now - _last_ms < MIN_GAP_MS:
		return false
	_last_ms = now
	var t := clampf((speed - SOFT_KNOCK) / (HARD_KNOCK - SOFT_KNOCK), 0.0, 1.0)
	output.call(lerpf(0.25, 0.7, t), lerpf(0.0, 0.5, t), lerpf(KNOCK_SHORTEST, KNOCK_LONGEST, t))
	return true


## A ball dropped into a hole: one long, strong buzz. True when it buzzed.
func drop() -> bool:
	if not enabled:
		return false
	output.call(0.6, 1.0, DROP_SECONDS)
	return true


## Rumbles every connected gamepad and buzzes a phone (Godot ignores the buzz elsewhere).
static func send_to_devices(weak: float, strong: float, seconds: float) -> void:
	for device in Input.get_connected_joypads():
		Input.start_joy_vibration(device, weak, strong, seconds)
	if OS.has_feature("mobile"):
		Input.vibrate_handheld(int(seconds * 1000.0), clampf(maxf(weak, strong), 0.0, 1.0))
