class_name TiltMixer
extends RefCounted
## Decides the board's tilt each frame from every control the player may use: the joystick
## (as in the seed: the tilt follows the head at once), keys and gamepad stick (a held key
## a tap nudges it and a hold rolls it on, KeyTilt), and a phone's
## accelerometer (relative to a calibrated neutral). The last control touched wins.

enum Source { NONE, JOYSTICK, KEYS, ACCELEROMETER }

## Accelerometer readings shorter than this (m/s²) mean the device has none.
const MIN_ACCEL := 0.5

## The tilt now, in degrees per axis.
var tilt := Vector2.ZERO
## Which control drives the tilt.
var source: Source = Source.NONE
## Scales keyboard, stick and accelerometer tilt (the settings' tilt sensitivity).
var sensitivity := 1.0
## The accelerometer reading that means "flat" (set by `calibrate`).
var neutral := Vector3.ZERO

var _last_accel := Vector3.ZERO
var _keys := KeyTilt.new()


## A tilt key (or the stick) went down toward `direction`, from its input event: the
## keys take the board and the next update nudges it, even when the key is up again by then.
func key_pressed(direction: Vector2) -> void:
	if direction == Vector2.ZERO:
		return
	if source != Source.KEYS:
		_keys.take_over(tilt / maxf(sensitivity, 0.01))
	source = Source.KEYS
	_keys.press(direction)


## The joystick head moved to `offset` seed pixels: the tilt follows at once.
func joystick_moved(offset: Vector2) -> void:
	source = Source.JOYSTICK
	tilt = TiltInput.tilt_from_joystick(offset)


## Advances one frame. `keys` is the tilt_* action vector (keyboard and stick, each axis
## -1..1; a press shorter than a frame comes through `key_pressed`); `accel` the
## accelerometer reading (zero on devices without one); `fine` whether the fine-tilt key is
## held (half tilt).
func update(delta: float, keys: Vector2, accel: Vector3, fine := false) -> Vector2:
	if keys.length_squared() > 0.0001:
		if source != Source.KEYS:
			_keys.take_over(tilt / maxf(sensitivity, 0.01))
		source = Source.KEYS
	if source == Source.KEYS:
		tilt = _keys.update(delta, keys, fine, sensitivity)
	_last_accel = accel
	if has_accelerometer() and source != Source.JOYSTICK and source != Source.KEYS:
		if neutral == Vector3.ZERO:
			calibrate()
		source = Source.ACCELEROMETER
		var target := TiltInput.tilt_from_accelerometer(accel, neutral, sensitivity)
		tilt = TiltInput.ease_toward(tilt, target, delta * 2.0)
	return tilt


## Records an accelerometer reading without moving the tilt (while the game waits), so the
## calibrate button knows whether the device has one.
func observe(accel: Vector3) -> void:
	_last_accel = accel


## True when the last reading came from a real accelerometer.
func has_accelerometer() -> bool:
	return _last_accel.length() > MIN_ACCEL


## Takes the current accelerometer reading as flat and hands control back to it, whichever
## control had it (the joystick too: moving it once must not lock the phone out).
func calibrate() -> void:
	if has_accelerometer():
		neutral = _last_accel
		source = Source.ACCELEROMETER


## Flattens the board and forgets which control was used (a reset).
func reset() -> void:
	tilt = Vector2.ZERO
	_keys.reset()
	if source != Source.ACCELEROMETER:
		source = Source.NONE
