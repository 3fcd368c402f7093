class_name PachinkoInput
extends RefCounted
## Turns the player's input into flipper and handle calls on the rules.
## The flipper (one shot): a press on the red grip and a drag up (mouse or touch, which
## Godot delivers as mouse events; the drag for full power is as long as the board is big
## on the screen, see drag_scale), the `launch_charge` action held and released (keyboard,
## gamepad button, or an analog axis whose depth sets the power), or the left stick pulled
## down (`tilt_down` from a joypad axis).
## The handle (a stream): held with the pointer on the dial (dragging while holding turns
## it: up or right stronger, down or left weaker), with the `launch_handle` key, or with the
## gamepad's right trigger, whose depth is the strength. `handle_stronger` / `handle_weaker`
## (held, they keep turning it: HandleKeyRepeat) and the mouse wheel on the dial turn it.

enum Source { NONE, POINTER, KEY, ANALOG }

## Stick pulls smaller than this are ignored.
const STICK_DEADZONE := 0.25
## Strength change per press of a turn key or notch of the wheel.
const HANDLE_STEP := 2.0
## Strength change per pixel of a drag on the held dial (up or right is stronger, down or
## left weaker, as the turn keys are: a play trial dragged left and the power rose).
const HANDLE_DRAG_PER_PIXEL := 0.5

## How many view units of drag make one point of power, relative to the rules' one pixel
## a point: the board's size on screen against the designed layout's (PachinkoGame sets
## it), so a full-power drag is the same share of the board in every window.
var drag_scale := 1.0

var _source := Source.NONE
var _drag_origin := Vector2.ZERO
var _peak := 0.0
var _handle_source := Source.NONE
var _handle_origin := Vector2.ZERO
var _handle_origin_power := 0.0
var _turn_repeat := HandleKeyRepeat.new()


## The pointer went down on the handle's dial at `at` (viewport coordinates): hold it.
func begin_handle_drag(rules: PachinkoRules, at: Vector2) -> void:
	if rules.state != PachinkoRules.State.PLAYING or _handle_source != Source.NONE:
		return
	_handle_source = Source.POINTER
	_handle_origin = at
	_handle_origin_power = rules.handle.power
	rules.handle.grip()


## The wheel turned over the dial by `notches` (up is positive).
func turn_handle(rules: PachinkoRules, notches: float) -> void:
	rules.handle.set_power(rules.handle.power + notches * HANDLE_STEP)


## Starts a pointer drawback at `at` (viewport coordinates).
func begin_drag(rules: PachinkoRules, at: Vector2) -> void:
	if rules.press_flipper(at):
		_source = Source.POINTER
		_drag_origin = at


## Mouse motion and release during a pointer drawback. True when the event was used.
func handle_pointer(rules: PachinkoRules, event: InputEvent, _owner: Node) -> bool:
	if _handle_source == Source.POINTER:
		return _handle_pointer(rules, event)
	if _source != Source.POINTER:
		return false
	var motion := event as InputEventMouseMotion
	if motion != null:
		rules.drag_to(_drag_point(motion.position))
		return true
	var button := event as InputEventMouseButton
	if button != null and not button.pressed and button.button_index == MOUSE_BUTTON_LEFT:
		rules.drag_to(_drag_point(button.position))
		rules.release()
		_source = Source.NONE
		return true
	return false


## Charge key, button, trigger and stick events. True when the event was used.
func handle_action(rules: PachinkoRules, event: InputEvent) -> bool:
	if _handle_action(rules, event):
		return true
	if _source == Source.POINTER:
		return false
	var axis := event as InputEventJoypadMotion
	if axis != null and (event.is_action("launch_charge") or event.is_action("tilt_down")):
		var strength := event.get_action_strength("launch_charge")
		if event.is_action("tilt_down"):
			strength = maxf(axis.axis_value, 0.0)
		return _analog(rules, strength)
	if event.is_action_pressed("launch_charge") and _source == Source.NONE:
		if rules.begin_charge():
			_source = Source.KEY
		return true
	if event.is_action_released("launch_charge") and _source == Source.KEY:
		rules.release()
		_source = Source.NONE
		return true
	return false


## Drops any drawback without firing. Called when the game pauses: a key or button let go
## while paused sends its release to no one, so without this the charge would go on
## climbing after the pause and the next press would be ignored.
func let_go(rules: PachinkoRules) -> void:
	if _source != Source.NONE:
		rules.cancel_draw()
	_source = Source.NONE
	_peak = 0.0
	_handle_source = Source.NONE
	_turn_repeat.stop()
	rules.handle.let_go()


## Called every frame: a held key keeps charging, a held turn key keeps turning.
func poll(rules: PachinkoRules, delta: float) -> void:
	if _source == Source.KEY:
		rules.charge(delta)
	var turns := _turn_repeat.advance(delta)
	if turns != 0:
		turn_handle(rules, turns)
	if _source != Source.NONE and not rules.drawing:
		_source = Source.NONE  # the game ended or restarted under us
	if _handle_source != Source.NONE and not rules.handle.held:
		_handle_source = Source.NONE


# The pointer at `at` as the rules measure a drag: its way from the press in board-sized
# units.
func _drag_point(at: Vector2) -> Vector2:
	return _drag_origin + (at - _drag_origin) / maxf(drag_scale, 0.01)


func _handle_pointer(rules: PachinkoRules, event: InputEvent) -> bool:
	var motion := event as InputEventMouseMotion
	if motion != null:
		var moved := motion.position - _handle_origin
		var turned := (moved.x - moved.y) * HANDLE_DRAG_PER_PIXEL
		rules.handle.set_power(_handle_origin_power + turned)
		return true
	var button := event as InputEventMouseButton
	if button != null and not button.pressed and button.button_index == MOUSE_BUTTON_LEFT:
		rules.handle.let_go()
		_handle_source = Source.NONE
		return true
	return false


# The handle key, the trigger (its depth is the strength) and the turn keys.
func _handle_action(rules: PachinkoRules, event: InputEvent) -> bool:
	var axis := event as InputEventJoypadMotion
	if axis != null and event.is_action("launch_handle"):
		var depth := absf(axis.axis_value)
		if depth > STICK_DEADZONE and rules.state == PachinkoRules.State.PLAYING:
			var share := (depth - STICK_DEADZONE) / (1.0 - STICK_DEADZONE)
			rules.handle.set_power(share * LaunchPower.MAX_POWER)
			if _handle_source == Source.NONE:
				_handle_source = Source.ANALOG
				rules.handle.grip()
		elif _handle_source == Source.ANALOG:
			rules.handle.let_go()
			_handle_source = Source.NONE
		return true
	if event.is_action_pressed("launch_handle") and _handle_source == Source.NONE:
		if rules.state == PachinkoRules.State.PLAYING:
			_handle_source = Source.KEY
			rules.handle.grip()
		return true
	if event.is_action_released("launch_handle") and _handle_source == Source.KEY:
		rules.handle.let_go()
		_handle_source = Source.NONE
		return true
	for turn: Array in [[&"handle_stronger", 1], [&"handle_weaker", -1]]:
		var action: StringName = turn[0]
		var toward: int = turn[1]
		if not event.is_action(action):
			continue
		# the system's echoes are dropped: the game repeats a held key itself, the same on
		# every machine (HandleKeyRepeat)
		if event.is_action_pressed(action):
			turn_handle(rules, _turn_repeat.press(toward))
		elif event.is_action_released(action):
			_turn_repeat.release(toward)
		return true
	return false


# An analog trigger or stick: the power follows its depth upwards; letting it spring back
# fires at the deepest point reached.
func _analog(rules: PachinkoRules, strength: float) -> bool:
	if strength > STICK_DEADZONE:
		if _source == Source.NONE:
			if not rules.begin_charge():
				return true
			_source = Source.ANALOG
			_peak = 0.0
		if _source == Source.ANALOG:
			_peak = maxf(_peak, strength)
			rules.set_power((_peak - STICK_DEADZONE) / (1.0 - STICK_DEADZONE) * 100.0)
		return true
	if _source == Source.ANALOG:
		rules.release()
		_source = Source.NONE
		return true
	return false
