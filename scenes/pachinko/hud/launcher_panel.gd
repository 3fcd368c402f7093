class_name LauncherPanel
extends Control
## The launcher: a vertical power bar that fills red from 0 to 100 (a gold mark keeps the
## last single shot's power), the flipper lever,
## which turns 0–20° with the power, and the handle's dial. A press on the lever starts a
## drawback (the game tracks the drag from there); a press on the dial holds the handle
## (a stream of balls) and the wheel over it turns it; the loaded-ball light shows whether
## a shot is ready. During a jackpot's rounds the strengths that feed the attacker are
## marked gold on the bar and the dial, and the hint says to aim there; an open tulip's
## strengths likewise (TulipBands). Given more room
## than its design size both ways (a phone's band under the board), it draws all of it
## bigger, to fill the room and be a bigger target.

## The pointer went down on the flipper at `at` (viewport coordinates).
signal flipper_pressed(at: Vector2)
## The pointer went down on the handle's dial at `at` (viewport coordinates).
signal handle_pressed(at: Vector2)
## The wheel turned over the dial: `notches` up (positive) or down.
signal handle_turned(notches: float)

## The room the launcher is drawn in at its design size; its minimum size.
const DESIGN_SIZE := Vector2(300, 250)
const BAR := Rect2(12, 44, 34, 180)
const PIVOT := Vector2(272, 196)
const LEVER_LENGTH := 150.0
const RED := Color("e23b3b")
## The handle's dial: centre and radius; its pointer sweeps DIAL_SWEEP_DEG for 0..100.
const DIAL_CENTER := Vector2(262, 92)
const DIAL_RADIUS := 27.0
const DIAL_START_DEG := 135.0
const DIAL_SWEEP_DEG := 270.0
const STREAM := Color("6cf07a")
## The mark on the bar at the last single shot's power.
const LAST_SHOT := Color("ffd34d")
## The strip by each band of strengths that paid this game, and its width on the bar.
const PAYING := Color("4be37a")
const PAYING_WIDTH := 12.0
## Font sizes of the launcher's words: the status line, and the rest (the hint beside the
## bar, POWER under it, HANDLE under the dial), which is the smallest text of the panel.
const STATUS_FONT_SIZE := 16
const SMALL_FONT_SIZE := 14
## The attacker's band while the rounds last (bar and dial) and its line.
const AIM := Color("ffb43a")

var _power := 0.0
var _degrees := 0.0
var _loaded := false
var _blocked := false
var _hint := ""
var _handle_held := false
var _handle_power := 0.0
var _last_shot := -1.0
var _paying: PayingStrengths
var _aim_band := Vector2i.ZERO
var _aim_words := ""


## Shows the current drawback.
func set_power(power: float, degrees: float) -> void:
	_power = power
	_degrees = degrees
	queue_redraw()


## Marks `power` on the bar as the last single shot's, so a good shot can be repeated.
func set_last_shot(power: float) -> void:
	_last_shot = power
	queue_redraw()


## Lights the bands of the bar whose strengths have been paying this game (`paying` is the
## game's tally; the panel reads it each time it draws).
func set_paying(paying: PayingStrengths) -> void:
	_paying = paying
	queue_redraw()


## Marks the strengths `band` (lowest, highest) that reach a target on the bar and the
## dial and swaps the hint for `words` (by default the attacker's, "Feed the attacker:
## stream at 75–85"; an open tulip's "Tulip open: power 55–65"); Vector2i.ZERO clears it.
func set_aim_band(band: Vector2i, words := "") -> void:
	_aim_band = band
	_aim_words = words if not words.is_empty() else AttackerBands.words(band)
	queue_redraw()


## The band marked now (Vector2i.ZERO: none).
func aim_band() -> Vector2i:
	return _aim_band


## The words beside the bar: the aim while a band is marked, else the controls hint.
func hint_text() -> String:
	if _aim_band == Vector2i.ZERO:
		return _hint
	return _aim_words.replace(": ", ":\n")


## The power the bar marks as the last single shot's (-1 before the first).
func last_shot() -> float:
	return _last_shot


## Lights the "ready" lamp while a ball is loaded.
func set_loaded(loaded: bool) -> void:
	_loaded = loaded
	queue_redraw()


## Shows that the launcher waits for a ball rolling back down the rail.
func set_blocked(blocked: bool) -> void:
	if blocked != _blocked:
		_blocked = blocked
		queue_redraw()


## The short line under the lever telling how to shoot.
func set_hint(text: String) -> void:
	_hint = text
	queue_redraw()


## The hint beside the lever: how to shoot once and stream, with the player's keys.
func show_controls_hint() -> void:
	set_hint(
		(
			(
				"One shot: drag the red\ngrip up or hold %s.\nStream: hold the dial\nor %s. Turn it"
				+ " with\n%s / %s."
			)
			% [
				KeyNames.of(&"launch_charge", "the charge key"),
				KeyNames.of(&"launch_handle", "the handle key"),
				KeyNames.of(&"handle_weaker", "?"),
				KeyNames.of(&"handle_stronger", "?"),
			]
		)
	)


## Shows the handle: held (streaming) or not, and its strength.
func set_handle(held: bool, power: float) -> void:
	_handle_held = held
	_handle_power = power
	queue_redraw()


## Asks for `times` (at least 1) its design size: the room it is then drawn in, as much
## bigger.
func draw_bigger(times: float) -> void:
	custom_minimum_size = DESIGN_SIZE * maxf(times, 1.0)


## How many times its design size the launcher is drawn: as far as its size allows both
## ways, never smaller than designed.
func art_scale() -> float:
	return maxf(1.0, minf(size.x / DESIGN_SIZE.x, size.y / DESIGN_SIZE.y))


## True when `local` (this control's coordinates) is on the handle's dial.
func is_on_handle(local: Vector2) -> bool:
	return local.distance_to(DIAL_CENTER * art_scale()) <= (DIAL_RADIUS + 6.0) * art_scale()


## True when `local` (this control's coordinates) is on the flipper lever.
func is_on_flipper(local: Vector2) -> bool:
	var lever := Transform2D(deg_to_rad(_degrees), PIVOT)
	var p := lever.affine_inverse() * (local / art_scale())
	return p.x > -LEVER_LENGTH - 24.0 and p.x < 20.0 and absf(p.y) < 30.0


func _ready() -> void:
	custom_minimum_size = DESIGN_SIZE
	mouse_default_cursor_shape = Control.CURSOR_POINTING_HAND


func _gui_input(event: InputEvent) -> void:
	var press := event as InputEventMouseButton
	if press == null or not press.pressed:
		return
	if is_on_handle(press.position):
		match press.button_index:
			MOUSE_BUTTON_LEFT:
				handle_pressed.emit(press.global_position)
			MOUSE_BUTTON_WHEEL_UP:
				handle_turned.emit(press.factor if press.factor > 0.0 else 1.0)
			MOUSE_BUTTON_WHEEL_DOWN:
				handle_turned.emit(-(press.factor if press.factor > 0.0 else 1.0))
		accept_event()
		return
	if press.button_index == MOUSE_BUTTON_LEFT:
		if is_on_flipper(press.position):
			flipper_pressed.emit(press.global_position)
			accept_event()


func _draw() -> void:
	draw_set_transform(Vector2.ZERO, 0.0, Vector2.ONE * art_scale())
	_draw_bar()
	_draw_lever()
	_draw_dial()
	var font := get_theme_default_font()
	var lamp_at := Vector2(BAR.position.x + 9.0, 16.0)
	draw_circle(lamp_at, 9.0, Color("1c1a24"))
	var lamp := Color("3b3f45")
	var status := "No ball loaded"
	if _loaded and _blocked:
		lamp = Color("f0b64a")
		status = "Wait: a ball is rolling back"
	elif _loaded and _handle_held:
		lamp = STREAM
		status = "Handle held: balls streaming"
	elif _loaded:
		lamp = Color("6cf07a")
		status = "Ball ready: fire!"
	draw_circle(lamp_at, 7.0, lamp)
	draw_string(
		font,
		lamp_at + Vector2(16, 6),
		status,
		HORIZONTAL_ALIGNMENT_LEFT,
		-1,
		STATUS_FONT_SIZE,
		Color("e9e3ff")
	)
	var lines := hint_text().split("\n")
	var aiming := _aim_band != Vector2i.ZERO
	for i in lines.size():
		draw_string(
			font,
			Vector2(BAR.end.x + 22.0, BAR.position.y + 6.0 + i * 18.0),
			lines[i],
			HORIZONTAL_ALIGNMENT_LEFT,
			-1,
			STATUS_FONT_SIZE if aiming else SMALL_FONT_SIZE,
			AIM if aiming else Color("b8aee0")
		)


func _draw_bar() -> void:
	draw_rect(BAR.grow(4.0), Color("14111d"))
	draw_rect(BAR, Color("2a2536"))
	var fill := BAR.size.y * clampf(_power / 100.0, 0.0, 1.0)
	var filled := Rect2(BAR.position + Vector2(0, BAR.size.y - fill), Vector2(BAR.size.x, fill))
	draw_rect(filled, RED)
	draw_rect(Rect2(filled.position, Vector2(6, filled.size.y)), RED.lightened(0.35))
	_draw_paying()
	if _aim_band != Vector2i.ZERO:
		# the attacker's strengths: a gold bracket down the bar's left side
		var low := BAR.end.y - BAR.size.y * _aim_band.x / 100.0
		var high := BAR.end.y - BAR.size.y * _aim_band.y / 100.0
		draw_rect(Rect2(BAR.position.x, high, 8.0, low - high), AIM)
		draw_rect(Rect2(BAR.position.x, high, BAR.size.x, low - high), AIM, false, 2.0)
	if _last_shot >= 0.0:
		# the last shot's mark: a gold line across the bar and a notch pointing at it
		var y := BAR.end.y - BAR.size.y * clampf(_last_shot / 100.0, 0.0, 1.0)
		draw_line(Vector2(BAR.position.x, y), Vector2(BAR.end.x, y), Color("14111d"), 5.0)
		draw_line(Vector2(BAR.position.x, y), Vector2(BAR.end.x, y), LAST_SHOT, 2.0)
		var notch := PackedVector2Array(
			[
				Vector2(BAR.end.x + 1.0, y),
				Vector2(BAR.end.x + 10.0, y - 6.0),
				Vector2(BAR.end.x + 10.0, y + 6.0)
			]
		)
		draw_colored_polygon(notch, LAST_SHOT)
	var font := get_theme_default_font()
	for i in 11:
		var y := BAR.end.y - BAR.size.y * i / 10.0
		var tick := 10.0 if i % 5 == 0 else 5.0
		draw_line(
			Vector2(BAR.position.x - tick, y), Vector2(BAR.position.x, y), Color("8a82aa"), 1.0
		)
	draw_string(
		font,
		Vector2(BAR.position.x - 6, BAR.end.y + 22),
		"POWER %d" % roundi(_power),
		HORIZONTAL_ALIGNMENT_LEFT,
		-1,
		SMALL_FONT_SIZE,
		Color("e9e3ff")
	)


# The strengths that paid this game: a green strip down the bar's right side by each band
# that paid back, the brighter the more it paid a ball, the best one edged in white.
func _draw_paying() -> void:
	if _paying == null:
		return
	var best := _paying.best_band()
	if best < 0:
		return
	var top := _paying.return_of(best)
	var band_height := BAR.size.y / PayingStrengths.BANDS
	for band in PayingStrengths.BANDS:
		var share := _paying.return_of(band) / top
		if share <= 0.0:
			continue
		var strip := Rect2(
			Vector2(BAR.end.x - PAYING_WIDTH, BAR.end.y - band_height * (band + 1) + 1.0),
			Vector2(PAYING_WIDTH, band_height - 2.0)
		)
		draw_rect(strip, Color(PAYING, 0.3 + 0.7 * share))
		if band == best:
			draw_rect(strip.grow(1.0), Color.WHITE, false, 1.5)


func _draw_lever() -> void:
	draw_set_transform(PIVOT * art_scale(), deg_to_rad(_degrees), Vector2.ONE * art_scale())
	var arm := Rect2(-LEVER_LENGTH, -9, LEVER_LENGTH, 18)
	draw_rect(arm.grow(2.0), Color("262233"))
	draw_rect(arm, Color("c4c9d6"))
	draw_rect(Rect2(arm.position, Vector2(arm.size.x, 5)), Color("eef1f7"))
	# The grip at the far end, and the pivot hub.
	draw_circle(Vector2(-LEVER_LENGTH, 0), 22.0, Color("262233"))
	draw_circle(Vector2(-LEVER_LENGTH, 0), 19.0, RED.darkened(0.1))
	draw_circle(Vector2(-LEVER_LENGTH - 5, -6), 7.0, RED.lightened(0.4))
	draw_set_transform(Vector2.ZERO, 0.0, Vector2.ONE * art_scale())
	draw_circle(PIVOT, 16.0, Color("262233"))
	draw_circle(PIVOT, 12.0, Color("9aa0b2"))
	draw_circle(PIVOT, 4.0, Color("262233"))
	if _power > 0.0:
		return
	# An arrow showing which way to pull.
	var tip := PIVOT + Vector2(-LEVER_LENGTH, -58)
	draw_line(tip + Vector2(0, 34), tip, Color(1, 1, 1, 0.45), 3.0, true)
	draw_colored_polygon(
		PackedVector2Array([tip + Vector2(0, -9), tip + Vector2(-7, 2), tip + Vector2(7, 2)]),
		Color(1, 1, 1, 0.45)
	)


func _draw_dial() -> void:
	var font := get_theme_default_font()
	var lit := STREAM if _handle_held else Color("8a82aa")
	draw_circle(DIAL_CENTER, DIAL_RADIUS + 4.0, Color("14111d"))
	draw_circle(DIAL_CENTER, DIAL_RADIUS, Color("2a2536"))
	var start := deg_to_rad(DIAL_START_DEG)
	var sweep := deg_to_rad(DIAL_SWEEP_DEG)
	var share := clampf(_handle_power / 100.0, 0.0, 1.0)
	draw_arc(DIAL_CENTER, DIAL_RADIUS - 5.0, start, start + sweep, 40, Color("3b3548"), 5.0, true)
	draw_arc(DIAL_CENTER, DIAL_RADIUS - 5.0, start, start + sweep * share, 40, lit, 5.0, true)
	if _aim_band != Vector2i.ZERO:
		var from := start + sweep * _aim_band.x / 100.0
		var to := start + sweep * _aim_band.y / 100.0
		draw_arc(DIAL_CENTER, DIAL_RADIUS + 1.0, from, to, 12, AIM, 4.0, true)
	var pointer := Vector2.from_angle(start + sweep * share)
	draw_line(DIAL_CENTER, DIAL_CENTER + pointer * (DIAL_RADIUS - 9.0), Color("eef1f7"), 4.0, true)
	draw_circle(DIAL_CENTER, 7.0, RED.darkened(0.1) if not _handle_held else STREAM.darkened(0.2))
	var label := "HANDLE %d" % roundi(_handle_power)
	var width := font.get_string_size(label, HORIZONTAL_ALIGNMENT_LEFT, -1, SMALL_FONT_SIZE).x
	var at := DIAL_CENTER + Vector2(-width * 0.5, DIAL_RADIUS + 18.0)
	draw_string(font, at, label, HORIZONTAL_ALIGNMENT_LEFT, -1, SMALL_FONT_SIZE, lit.lightened(0.3))
