class_name GoldPinsView
extends Node
## Wires the gold pins to a game: the studs, bursts and aim rings (GoldPinLayer) under the
## board view's balls, a bright chime for each pin put out (higher as the set empties),
## and the set's prize announced large by the jackpot's banner once it is free (one
## announcement at a time), with a peal of bells.

## Seconds the prize's announcement shows (the reach of a Gold spin comes up at the top meanwhile).
const ANNOUNCE_SECONDS := 2.0

var layer := GoldPinLayer.new()

var _board_view: BoardView
var _sounds: SoundBank
var _bonus_view: BonusView
var _rules: PachinkoRules
## The announcement waiting for the banner: [title, subtitle], or empty.
var _waiting := PackedStringArray()


## Adds the layer to `board_view` (under its balls); sounds go to `sounds`, the prize's
## announcement to `bonus_view`'s banner.
func attach(board_view: BoardView, sounds: SoundBank, bonus_view: BonusView) -> void:
	_board_view = board_view
	_sounds = sounds
	_bonus_view = bonus_view
	layer.name = "GoldPins"
	board_view.add_child(layer)
	board_view.move_child(layer, board_view.balls.get_index())
	SoundBank.warm(GoldRecipes.names())
	set_process(false)


## Follows the game of `rules` (a new game's rules each time); call after the board view
## is bound to them. Measures the board's PinReach now, while the game loads, so the first
## shot does not wait for it.
func bind(rules: PachinkoRules) -> void:
	_rules = rules
	_waiting = PackedStringArray()
	PinReach.of(rules.level)
	layer.bind(rules, _board_view.aim_preview())
	rules.gold.pin_out.connect(_on_pin_out)
	rules.gold.set_cleared.connect(_on_set_cleared)


## The announcement waiting for the banner ("" when none).
func waiting_title() -> String:
	return _waiting[0] if not _waiting.is_empty() else ""


func _process(_delta: float) -> void:
	if _waiting.is_empty():
		set_process(false)
	elif not _bonus_view.holds_the_stage():
		var level := _rules.level
		_bonus_view.banner.show_moment(
			level.ring_center, level.ring_radius, _waiting[0], _waiting[1], ANNOUNCE_SECONDS
		)
		_waiting = PackedStringArray()


func _on_pin_out(_pin: int, left: int) -> void:
	if _sounds != null:
		_sounds.play(GoldRecipes.GOLD_CHIME, -3.0, 1.0 + 0.04 * maxi(8 - left, 0))


func _on_set_cleared(_set_number: int, spin: bool) -> void:
	if _sounds != null:
		_sounds.play(GoldRecipes.GOLD_PRIZE, -1.0)
	_waiting = GoldPinsText.announcement(spin)
	set_process(true)
