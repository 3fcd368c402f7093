class_name MazeJoystick
extends Control
## The seed's joystick: a dark purple disc with four arrows and a red-orange head. Press the
## head to start; after that the head follows the pointer (clamped to ±15 seed pixels per
## axis) as in the seed, and `moved` reports the offset, which the game turns into tilt.
## As in the seed, 15 screen pixels of pointer travel tilt the board all the way (divided by
## `sensitivity`), however large the joystick is drawn.
## The head pulses until it is first used. Sizes are the seed's times `ui_scale`.

## The head was pressed (the seed's "click the joystick to start").
signal pressed
## The head moved to `offset` seed pixels from the centre (each axis within ±15).
signal moved(offset: Vector2)

const DISC_RADIUS := 25.0
const HEAD_RADIUS := 10.0
const ARROW_DISTANCE := 55.0
const ARROW_HALF := 10.0
## The seed waits 4 s before the head starts to pulse, then pulses 0.6 s each way.
const GLOW_DELAY := 4.0
const GLOW_PERIOD := 0.6

## Screen pixels per seed pixel, for drawing. Starts at the size the maze panel gives it
## (MazePanelLayout.JOYSTICK_SCALE), so the panel fits from its first frame (a play trial saw
## it drawn at double size, cut off, during "Loading…").
@export var ui_scale := 1.0:
	set(value):
		ui_scale = maxf(value, 0.5)
		custom_minimum_size = Vector2.ONE * drawn_size(ui_scale)
		queue_redraw()
## Scales the pointer's travel (the settings' tilt sensitivity): at 1 a pointer moved 15
## screen pixels tilts the board fully, as in the seed; at 2, 7.5 pixels do.
var sensitivity := 1.0

## Where the head is drawn, in seed pixels from the centre.
var head_offset := Vector2.ZERO:
	set(value):
		head_offset = TiltInput.clamp_joystick(value)
		queue_redraw()
## True until the head is first pressed: it pulses to draw the eye.
var glowing := true
## True while the head follows the pointer.
var engaged := false
## True while the fine-tilt key is held: "FINE" shows in the corner and a ring marks how far
## the head goes then (the keys tilt at most KeyTilt.FINE_SCALE of full). Trial 10: "I never
## saw Shift fine tilt make a noticeable difference".
var fine := false:
	set(value):
		fine = value
		if _fine_label != null:
			_fine_label.visible = value
		queue_redraw()

var _fine_label: Label

var _grab_point := Vector2.ZERO
var _clock := 0.0


func _ready() -> void:
	custom_minimum_size = Vector2.ONE * drawn_size(ui_scale)
	mouse_filter = Control.MOUSE_FILTER_STOP
	_fine_label = Label.new()
	_fine_label.name = "Fine"
	_fine_label.text = "FINE"
	_fine_label.mouse_filter = Control.MOUSE_FILTER_IGNORE
	_fine_label.add_theme_color_override("font_color", MazePalette.TEXT)
	_fine_label.visible = fine
	add_child(_fine_label)


## The fine key's label ("FINE", shown while the key is held).
func fine_label() -> Label:
	return _fine_label


func _process(delta: float) -> void:
	_clock += delta
	if glowing:
		queue_redraw()


## The width and height (px) the joystick and its arrows take at `drawn_scale`.
static func drawn_size(drawn_scale: float) -> float:
	return (ARROW_DISTANCE + ARROW_HALF + 8.0) * 2.0 * drawn_scale


## Stops following the pointer and centres the head (a reset or the end of a game).
func release() -> void:
	engaged = false
	head_offset = Vector2.ZERO


func _gui_input(event: InputEvent) -> void:
	var press := event as InputEventMouseButton
	if press == null or not press.pressed or press.button_index != MOUSE_BUTTON_LEFT:
		return
	var head := size * 0.5 + head_offset * ui_scale
	if press.position.distance_to(head) > (HEAD_RADIUS + 8.0) * ui_scale:
		return
	accept_event()
	glowing = false
	engaged = true
	_grab_point = press.global_position - head_offset / _gain()
	pressed.emit()
	queue_redraw()


func _input(event: InputEvent) -> void:
	if not engaged:
		return
	var up := event as InputEventMouseButton
	if up != null and not up.pressed and up.button_index == MOUSE_BUTTON_LEFT:
		# let go: the head springs back and the board levels (a play trial's board stayed
		# tilted after the mouse came up, until a key was pressed)
		release()
		moved.emit(head_offset)
		return
	var motion := event as InputEventMouseMotion
	if motion == null:
		return
	head_offset = (motion.global_position - _grab_point) * _gain()
	moved.emit(head_offset)


## Seed pixels of head travel per screen pixel of pointer travel.
func _gain() -> float:
	return maxf(sensitivity, 0.01)


func _draw() -> void:
	var c := size * 0.5
	var s := ui_scale
	draw_circle(c, DISC_RADIUS * s, MazePalette.JOYSTICK)
	for dir: Vector2 in [Vector2.UP, Vector2.DOWN, Vector2.LEFT, Vector2.RIGHT]:
		var tip := c + dir * (ARROW_DISTANCE + ARROW_HALF) * s
		var base := c + dir * ARROW_DISTANCE * s
		var side := dir.orthogonal() * ARROW_HALF * s
		draw_colored_polygon(
			PackedVector2Array([tip, base + side, base - side]), MazePalette.JOYSTICK
		)
	if fine:
		# the head's reach with the fine key: the keys' tilt at its most, as the head shows it
		var most := TiltInput.MAX_TILT_DEG * KeyTilt.FINE_SCALE
		var reach := TiltInput.joystick_from_tilt(Vector2(most, 0.0)).x + HEAD_RADIUS
		draw_arc(c, reach * s, 0.0, TAU, 48, Color(MazePalette.BALL, 0.8), 2.0 * s, true)
	var radius := HEAD_RADIUS * s * _glow_scale()
	var head := c + head_offset * s
	if glowing:
		draw_circle(head, radius * 1.35, Color(MazePalette.BALL, 0.25))
	draw_circle(head, radius, MazePalette.BALL)
	draw_circle(head + Vector2(-0.3, -0.35) * radius, radius * 0.3, MazePalette.BALL.lightened(0.4))


# The seed's glow: scale 1 → 1.2 and back, ease-in-out, after a 4 s delay.
func _glow_scale() -> float:
	if not glowing or _clock < GLOW_DELAY:
		return 1.0
	var phase := fmod((_clock - GLOW_DELAY) / GLOW_PERIOD, 2.0)
	var t := phase if phase <= 1.0 else 2.0 - phase
	return 1.0 + 0.2 * (0.5 - 0.5 * cos(t * PI))
