class_name FeverGlow
extends Node2D
## The fever state: while a jackpot is on (its rounds and the breaks between them) the ring
## burns with a pulsing warm band, and the round ("ROUND 3 / 10") with its seconds and
## catches left hangs over the top of the field, so a player knows at a glance that now is
## the time to feed the attacker. The ring's band is drawn under the balls; the caption is a
## plaque of its own over everything (balls, aim dots), placed inside the ring's inner edge
## (a play trial found it clipped under the rim, with the aim dots drawn over it), under the
## reels (another found it over their digits).

const RING_WIDTH := 14.0
const WARM := Color("ff8a2a")
const HOT := Color("ffd84a")
## The caption's font size, board pixels, and the room around it on its plaque.
const CAPTION_SIZE := 22
const PLAQUE_PAD := Vector2(14.0, 6.0)
## Room kept between the plaque and the ring's inner edge (the rim's lights), board pixels.
const RIM_ROOM := 14.0
## Room under the reels' window for its spin lamps (ReelDisplay), board pixels.
const REEL_LAMPS_ROOM := 18.0
## The plaque's z: over the balls, the aim dots and the board's other layers.
const PLAQUE_Z := 100

## The reach stage (the big reels): while it is up the plaque goes under it (trial 6: the
## ROUND pill across the 5 5 5 just won). Null: none.
var stage: ReachStage
## The jackpot's banner: while it announces a round the plaque waits (trial 7: a banner's
## "ROUND 1 / 10" and the plaque's lay one over the other). Null: none.
var banner: JackpotBanner

var _level: BoardLevel
var _machine: BonusMachine
var _clock := 0.0
## The caption's plaque: a layer of its own, drawn over everything on the board.
var _plaque := Node2D.new()


func _init() -> void:
	_plaque.name = "CaptionPlaque"
	_plaque.z_index = PLAQUE_Z
	_plaque.draw.connect(_draw_caption)
	add_child(_plaque)


## Shows the fever state of `machine` on `level`.
func bind(level: BoardLevel, machine: BonusMachine) -> void:
	_level = level
	_machine = machine
	queue_redraw()


## True while the fever state shows (a jackpot is on, or an attacker is open).
func is_lit() -> bool:
	return _machine != null and (_machine.rounds.active() or _machine.any_attacker_open())


## The words over the field during fever: the round, and the seconds and catches left of
## the first open attacker ("ROUND 3 / 10  5s  8 to catch"), the break before the next
## round, or "" when no jackpot is on.
func caption() -> String:
	if not is_lit():
		return ""
	var round_text := "ROUND %d / %d" % [_machine.rounds.current_round, JackpotRounds.ROUNDS]
	if _machine.rounds.in_break():
		return "%s  next round…" % round_text
	for i in _level.bonus_pockets.size():
		if _machine.is_open(i) and _level.bonus_pockets[i].role == BonusPocketSpec.Role.ATTACKER:
			return (
				"%s  %ds  %d to catch"
				% [round_text, ceili(_machine.time_left(i)), _machine.catches_left(i)]
			)
	return round_text


## True while the caption's plaque is drawn: fever is lit and neither the reach stage nor a
## banner holds the board (one announcement at a time).
func caption_shown() -> bool:
	if not is_lit():
		return false
	return (
		not (stage != null and stage.is_on_stage()) and not (banner != null and banner.is_showing())
	)


## The caption's plaque on the board (board pixels): centred on the ring's middle line, just
## under the reels' window and its lamps on a board with reels (a play trial found it over
## the reels' digits), under the reach stage while it shows, else as high as it fits inside
## the ring's inner edge. Empty while no caption shows.
func caption_rect() -> Rect2:
	var text := caption()
	if text.is_empty():
		return Rect2()
	var font := ThemeDB.fallback_font
	var size := (
		font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, CAPTION_SIZE) + PLAQUE_PAD * 2.0
	)
	var centre := _level.ring_center
	if BonusGeometry.has_reels(_level):
		var under := BonusGeometry.reel_window(_level).end.y + REEL_LAMPS_ROOM
		if stage != null and stage.is_on_stage():
			under = maxf(under, stage.stage_rect().end.y + REEL_LAMPS_ROOM)
		return Rect2(Vector2(centre.x - size.x * 0.5, under), size)
	var inner := _level.ring_radius - RING_WIDTH - RIM_ROOM
	# the top corners are the ones nearest the rim: they sit on the inner circle
	var rise := sqrt(maxf(inner * inner - size.x * size.x * 0.25, 0.0))
	return Rect2(Vector2(centre.x - size.x * 0.5, centre.y - rise), size)


## The caption's plaque layer (for tests: it is drawn over everything).
func plaque() -> Node2D:
	return _plaque


func _process(delta: float) -> void:
	_clock += delta
	if is_lit() or visible:
		queue_redraw()
		_plaque.queue_redraw()


func _draw() -> void:
	if not is_lit():
		return
	var pulse := 0.5 + 0.5 * sin(_clock * 9.0)
	var centre := _level.ring_center
	var radius := _level.ring_radius - RING_WIDTH * 0.5
	draw_arc(centre, radius, 0.0, TAU, 96, Color(WARM, 0.35 + 0.3 * pulse), RING_WIDTH, true)
	draw_arc(centre, radius, 0.0, TAU, 96, Color(HOT, 0.5 + 0.5 * pulse), 2.0, true)


func _draw_caption() -> void:
	if _level == null or not caption_shown():
		return
	var rect := caption_rect()
	var pulse := 0.5 + 0.5 * sin(_clock * 9.0)
	var box := StyleBoxFlat.new()
	box.bg_color = Color(0.05, 0.02, 0.08, 0.9)
	box.border_color = WARM.lerp(HOT, pulse)
	box.set_border_width_all(2)
	box.set_corner_radius_all(8)
	_plaque.draw_style_box(box, rect)
	var font := ThemeDB.fallback_font
	var at := Vector2(rect.position.x + PLAQUE_PAD.x, rect.position.y + PLAQUE_PAD.y)
	at.y += font.get_ascent(CAPTION_SIZE)
	var text := caption()
	_plaque.draw_string(font, at, text, HORIZONTAL_ALIGNMENT_LEFT, -1, CAPTION_SIZE, HOT)
