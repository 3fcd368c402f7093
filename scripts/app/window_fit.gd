class_name WindowFit
extends RefCounted
## The game window's size at start: on a first start the designed 1280 × 720, made smaller
## (same shape) until it fits the screen's usable area (the desktop less its panels); on a
## later start the size the player left it at, cut down to the screen when that is smaller
## now. Never larger than the screen, never smaller than MINIMUM. Room for a window frame is
## kept only where a desktop reserves part of the screen (its panels): a bare X server has no
## frames, and trial 9 saw a 1201 x 676 window 33 px in on a 1280 x 720 one.

## The design size the layouts are made for (project.godot's viewport size).
const DESIGN := Vector2i(1280, 720)
## Room kept for the window manager's frame and title bar, which the usable area includes.
const FRAME_ALLOWANCE := Vector2i(12, 44)
## The smallest window the layouts still work in.
const MINIMUM := Vector2i(480, 360)


## The window size for a first start on a screen whose usable area is `usable`: the design
## size, or the largest of its shape that fits with `frame` (the window frame's room) kept.
static func first_size(usable: Vector2i, frame := FRAME_ALLOWANCE) -> Vector2i:
	var room := _room(usable, frame)
	var scale := minf(1.0, minf(float(room.x) / float(DESIGN.x), float(room.y) / float(DESIGN.y)))
	var fitted := Vector2i(floori(DESIGN.x * scale), floori(DESIGN.y * scale))
	return fitted.max(MINIMUM).min(room)


## The size the player left the window at, cut to fit `usable` (each side on its own: a
## player's shape is theirs). `frame`: the room kept for the window's frame.
static func remembered_size(
	remembered: Vector2i, usable: Vector2i, frame := FRAME_ALLOWANCE
) -> Vector2i:
	return remembered.max(MINIMUM).min(_room(usable, frame))


## The room kept for a window frame on a screen of `screen` whose usable area is `usable`:
## none when the usable area is the whole screen (no desktop panels: a bare X server, where
## windows have no frames, or a kiosk), else FRAME_ALLOWANCE.
static func frame_room(usable: Rect2i, screen: Rect2i) -> Vector2i:
	return Vector2i.ZERO if usable == screen else FRAME_ALLOWANCE


## The top-left corner that centres a window of `size` in the usable area `usable`.
static func centred(size: Vector2i, usable: Rect2i) -> Vector2i:
	@warning_ignore("integer_division")  # whole pixels: half a pixel more on one side is fine
	var margin := ((usable.size - size) / 2).max(Vector2i.ZERO)
	return usable.position + margin


## Sizes and centres the game's main window for its screen: `remembered` is the player's
## last window size (Vector2i.ZERO when none). Returns the size set, or Vector2i.ZERO when
## the window was left alone (no display, fullscreen or maximised, no usable area known).
## Through the Window, not the DisplayServer alone, so the view is stretched to the new size.
static func fit_window(window: Window, remembered: Vector2i) -> Vector2i:
	if DisplayServer.get_name() == "headless":
		return Vector2i.ZERO
	if window.mode != Window.MODE_WINDOWED:
		return Vector2i.ZERO
	var screen := window.current_screen
	var usable := DisplayServer.screen_get_usable_rect(screen)
	if usable.size.x <= 0 or usable.size.y <= 0:
		return Vector2i.ZERO
	var whole := Rect2i(
		DisplayServer.screen_get_position(screen), DisplayServer.screen_get_size(screen)
	)
	var frame := frame_room(usable, whole)
	var size := (
		first_size(usable.size, frame)
		if remembered == Vector2i.ZERO
		else remembered_size(remembered, usable.size, frame)
	)
	window.size = size
	window.position = centred(size + frame, usable)
	return size


# The client area a window can have on a usable area of `usable`, frame left out.
static func _room(usable: Vector2i, frame: Vector2i) -> Vector2i:
	return (usable - frame).max(Vector2i.ONE)
