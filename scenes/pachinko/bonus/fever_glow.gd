class_name FeverGlow
extends Node2D
## The fever state: while a jackpot is on (its rounds and the breaks between them) the ring
## burns with a pulsing warm band, and the round ("ROUND 3 / 10") with its seconds and
## catches left hangs over the top of the field, so a player knows at a glance that now is
## the time to feed the attacker. Drawn over the board, under nothing: it only tints the
## edge.

const RING_WIDTH := 14.0
const WARM := Color("ff8a2a")
const HOT := Color("ffd84a")

var _level: BoardLevel
var _machine: BonusMachine
var _clock := 0.0


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


func _process(delta: float) -> void:
	_clock += delta
	if is_lit() or visible:
		queue_redraw()


func _draw() -> void:
	if not is_lit():
		return
	var pulse := 0.5 + 0.5 * sin(_clock * 9.0)
	var centre := _level.ring_center
	var radius := _level.ring_radius - RING_WIDTH * 0.5
	draw_arc(centre, radius, 0.0, TAU, 96, Color(WARM, 0.35 + 0.3 * pulse), RING_WIDTH, true)
	draw_arc(centre, radius, 0.0, TAU, 96, Color(HOT, 0.5 + 0.5 * pulse), 2.0, true)
	var font := ThemeDB.fallback_font
	var text := caption()
	var size := 22
	var width := font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, size).x
	var at := centre + Vector2(-width * 0.5, -_level.ring_radius + 52.0)
	draw_string_outline(font, at, text, HORIZONTAL_ALIGNMENT_LEFT, -1, size, 5, Color(0, 0, 0))
	draw_string(font, at, text, HORIZONTAL_ALIGNMENT_LEFT, -1, size, WARM.lerp(HOT, pulse))
