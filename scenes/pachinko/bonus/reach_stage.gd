class_name ReachStage
extends Node2D
## The reach on centre stage: when the first two reels match, the reels come out of their
## small window, large (each reel's number SYMBOL_FONT_SIZE board pixels, about 81 px
## tall at 1280 × 720), the last reel slowing down under "REACH!"; it stands in the top
## part of the board, over the reels' window, like a real machine's screen in its centre
## piece; on a jackpot the three numbers flash gold under "JACKPOT!" a moment before the
## stage goes. Drawn over the balls (trial 7 found balls across its reels); it keeps to the
## board's top, where few balls fly; play goes on (slowed by ReachSlowMotion).

## Seconds the stage takes to come in and to go.
const GROW_SECONDS := 0.25
## Seconds the stage stays after the last reel stopped: longer on a jackpot.
const HOLD_MISS := 0.7
const HOLD_JACKPOT := 1.6
## One reel's box, board pixels, and the gap between two.
const BOX := Vector2(92.0, 124.0)
const GAP := 10.0
## The numbers' font size, board pixels (a digit is about 0.7 of it tall).
const SYMBOL_FONT_SIZE := 124
## "REACH!" / "JACKPOT!" over the reels, font size in board pixels, and the room it takes.
const TITLE_SIZE := 44
const TITLE_ROOM := 52.0
## How visible the stage stays while the player aims (see_through): trial 9 charged a shot
## under a reach and fired blind, the reels over the aim's arc and landing circle.
const AIMING_ALPHA := 0.25
## Seconds the stage takes to fade for the aim and to come back.
const SEE_THROUGH_SECONDS := 0.15
## Room kept between the stage's top corners and the ring, board pixels (the rim's width).
const RIM_ROOM := 14.0
## The stage's frame around the reels' panel.
const FRAME := 10.0

## True while the player aims: the stage fades to AIMING_ALPHA so the aim's arc shows.
var see_through := false

var _machine: BonusMachine
var _center := Vector2.ZERO
## 0 hidden .. 1 fully on stage.
var _shown := 0.0
## Seconds left to hold the stage after the last reel stopped (-1: no reach ended).
var _hold := -1.0
var _jackpot := false
var _clock := 0.0


## Stages `machine`'s reaches in `level`'s ring, above the pockets under its middle.
func bind(level: BoardLevel, machine: BonusMachine) -> void:
	_machine = machine
	_center = place_on(level)
	_shown = 0.0
	_hold = -1.0
	machine.reach_ended.connect(_on_reach_ended)
	visible = BonusGeometry.has_reels(level)
	set_process(visible)
	queue_redraw()


## Where the reels stand while a reach lasts (the panel's centre, board pixels).
func center() -> Vector2:
	return _center


## The whole stage at full size ("REACH!" and the reels' frame), board pixels.
func stage_rect() -> Rect2:
	return _rect_at(_center)


## Where the stage's centre goes on `level`: on the ring's middle line, as high as the ring
## lets it stand (its top corners RIM_ROOM inside the ring), over the reels' own window. Play
## trials found it covering the middle of the board: first 110 px numbers in the very
## middle, then a stage just above the pockets that still hid the pins the balls fall
## through; up here the lower board, its pockets and pins stay in view.
static func place_on(level: BoardLevel) -> Vector2:
	var middle := level.ring_center
	var half := _rect_at(Vector2.ZERO)
	var reach := level.ring_radius - RIM_ROOM
	var rise := sqrt(maxf(reach * reach - pow(half.size.x * 0.5, 2.0), 0.0))
	return Vector2(middle.x, middle.y - rise - half.position.y)


static func _rect_at(middle: Vector2) -> Rect2:
	var width := BOX.x * ReelSet.REELS + GAP * (ReelSet.REELS + 1) + FRAME * 2.0
	var height := BOX.y + GAP * 2.0 + FRAME * 2.0
	return Rect2(
		middle + Vector2(-width * 0.5, -height * 0.5 - TITLE_ROOM),
		Vector2(width, height + TITLE_ROOM)
	)


## True while the stage shows (coming in, on, or going).
func is_on_stage() -> bool:
	return _shown > 0.0


func _process(delta: float) -> void:
	if _machine == null:
		return
	_clock += delta
	var wanted := _machine.reels.in_reach() or _hold > 0.0
	if _hold > 0.0:
		_hold -= delta
	var before := _shown
	_shown = move_toward(_shown, 1.0 if wanted else 0.0, delta / GROW_SECONDS)
	var alpha := AIMING_ALPHA if see_through else 1.0
	modulate.a = move_toward(modulate.a, alpha, delta / SEE_THROUGH_SECONDS)
	if _shown > 0.0 or before > 0.0:
		queue_redraw()  # off stage there is nothing to draw, frame after frame


func _on_reach_ended(jackpot: bool) -> void:
	_jackpot = jackpot
	_hold = HOLD_JACKPOT if jackpot else HOLD_MISS


func _draw() -> void:
	if _machine == null or _shown <= 0.0:
		return
	var grow := ease(_shown, -2.0)
	draw_set_transform(_center, 0.0, Vector2.ONE * lerpf(0.35, 1.0, grow))
	var reels := _machine.reels
	var width := BOX.x * ReelSet.REELS + GAP * (ReelSet.REELS + 1)
	var panel := Rect2(Vector2(-width * 0.5, -BOX.y * 0.5 - GAP), Vector2(width, BOX.y + GAP * 2.0))
	var alpha := grow
	var pulse := 0.5 + 0.5 * sin(_clock * 10.0)
	# a won reach says JACKPOT! until the stage has gone: going, it read "REACH!" again
	var won := _jackpot and not reels.in_reach()
	var rim := Color("ffd84a") if won else Color(1.0, 0.35 + 0.3 * pulse, 0.2)
	draw_rect(panel.grow(FRAME), Color(rim, 0.85 * alpha))
	draw_rect(panel, Color(0.03, 0.02, 0.07, 0.88 * alpha))
	var font := ThemeDB.fallback_font
	for reel in ReelSet.REELS:
		var box := Rect2(panel.position + Vector2(GAP + reel * (BOX.x + GAP), GAP), BOX)
		var last := reel == ReelSet.REELS - 1
		draw_rect(box, Color(0.13, 0.1, 0.22, alpha))
		if last and reels.in_reach():
			# The deciding reel glows hotter as it slows.
			var heat := reels.reach_progress()
			draw_rect(box, Color(1.0, 0.5, 0.1, (0.15 + 0.35 * heat * pulse) * alpha))
		var symbol := reels.shown_symbol(reel)
		var text := ReelDisplay.face_text(symbol)
		var color: Color = ReelDisplay.SYMBOL_COLORS[
			maxi(symbol, 0) % ReelDisplay.SYMBOL_COLORS.size()
		]
		if won:
			color = Color("fff3a0").lerp(Color("ffb000"), pulse)
		var text_width := (
			font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, SYMBOL_FONT_SIZE).x
		)
		var base := Vector2(
			box.get_center().x - text_width * 0.5,
			box.get_center().y + font.get_ascent(SYMBOL_FONT_SIZE) * 0.36
		)
		if reels.is_spinning(reel):
			# A rolling number slides down through its box.
			var slide := (fmod(reels.roll_position(reel), 1.0) - 0.5) * BOX.y * 0.5
			base.y += slide
		draw_string_outline(
			font,
			base,
			text,
			HORIZONTAL_ALIGNMENT_LEFT,
			-1,
			SYMBOL_FONT_SIZE,
			10,
			Color(0, 0, 0, alpha)
		)
		draw_string(
			font, base, text, HORIZONTAL_ALIGNMENT_LEFT, -1, SYMBOL_FONT_SIZE, Color(color, alpha)
		)
	var title := "JACKPOT!" if won else "REACH!"
	var title_width := font.get_string_size(title, HORIZONTAL_ALIGNMENT_LEFT, -1, TITLE_SIZE).x
	var at := Vector2(-title_width * 0.5, panel.position.y - FRAME - 12.0)
	draw_string_outline(
		font, at, title, HORIZONTAL_ALIGNMENT_LEFT, -1, TITLE_SIZE, 10, Color(0.3, 0.0, 0.05, alpha)
	)
	draw_string(font, at, title, HORIZONTAL_ALIGNMENT_LEFT, -1, TITLE_SIZE, Color(rim, alpha))
	draw_set_transform(Vector2.ZERO)
