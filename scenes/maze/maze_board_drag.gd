class_name MazeBoardDrag
extends Node
## A mouse drag that starts on the board tilts it, as the joystick does (trial 9: "the mouse
## joystick allows partial tilt, but it is small and sits far from the board"). The drag's
## vector from the press point is a joystick head offset, so it has the joystick's dead zone
## and gentle curve (TiltInput.tilt_from_joystick); a drag of FULL_DRAG_SHARE of the board's
## shorter side tilts fully (at tilt sensitivity 1), so a click without a drag leaves it
## level. Letting go levels the board. Presses on the panels over the board never reach it
## (they are handled first); the drag's moves and let-go are heard wherever the pointer is.

## A left press on the board (the joystick's `pressed`).
signal pressed
## The drag is at `offset` seed pixels of joystick head travel (zero when let go).
signal moved(offset: Vector2)

## A drag this part of the board's shorter side (on screen) tilts the board fully.
const FULL_DRAG_SHARE := 0.125
## ...and never less than this many screen pixels (a board drawn small).
const FULL_DRAG_MIN_PX := 40.0

## The board's region on screen (viewport pixels); a press outside it is not a drag.
var region := Rect2()
## True from a press on the board until the button comes up.
var dragging := false
## The drag now as a joystick head offset (seed pixels; TiltInput.JOYSTICK_RANGE is full).
var offset := Vector2.ZERO
## Scales the drag (the settings' tilt sensitivity), as the joystick's.
var sensitivity := 1.0
## False while the board takes no drag (no board loaded).
var enabled := true

var _from := Vector2.ZERO
var _full_px := 60.0


func _unhandled_input(event: InputEvent) -> void:
	var button := event as InputEventMouseButton
	if not enabled or button == null or button.button_index != MOUSE_BUTTON_LEFT:
		return
	if button.pressed and not dragging and region.has_point(button.position):
		dragging = true
		_from = button.position
		_full_px = maxf(minf(region.size.x, region.size.y) * FULL_DRAG_SHARE, FULL_DRAG_MIN_PX)
		offset = Vector2.ZERO
		get_viewport().set_input_as_handled()
		pressed.emit()


func _input(event: InputEvent) -> void:
	if not dragging:
		return
	var button := event as InputEventMouseButton
	if button != null and button.button_index == MOUSE_BUTTON_LEFT and not button.pressed:
		release()
		moved.emit(offset)
		return
	var motion := event as InputEventMouseMotion
	if motion == null:
		return
	var drag := (motion.position - _from) / _full_px * TiltInput.JOYSTICK_RANGE
	offset = TiltInput.clamp_joystick(drag * maxf(sensitivity, 0.01))
	moved.emit(offset)


## Ends the drag (a reset, the end of a run): the offset back to the centre.
func release() -> void:
	dragging = false
	offset = Vector2.ZERO
