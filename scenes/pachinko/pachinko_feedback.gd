class_name PachinkoFeedback
extends RefCounted
## What the player sees and hears as the rules report a game: the launcher's lamp, power and
## last-shot mark, the cup's count and pour, a pocket's celebration, the gutter's flash, the
## pin ticks and every shot's sound, what each band of strengths has paid (lit on the
## launcher's bar), and during a jackpot's rounds the strengths that feed the attacker.
## PachinkoGame makes one and binds it to each new game's rules.

## Impact speeds (px/s) mapped onto the pin tick's quietest and loudest.
const TICK_MIN_SPEED := 40.0
const TICK_MAX_SPEED := 700.0

## What each band of launch strengths has paid this game (lit on the launcher's bar).
var paying := PayingStrengths.new()

var _board_view: BoardView
var _launcher: LauncherPanel
var _cup: CupDisplay
var _sounds: SoundBank
var _rules: PachinkoRules
# The tulips open now (bonus indices, in the order they opened): the launcher marks the
# band of the last one (TulipBands).
var _open_tulips: Array[int] = []


func _init(
	board_view: BoardView, launcher: LauncherPanel, cup: CupDisplay, sounds: SoundBank
) -> void:
	_board_view = board_view
	_launcher = launcher
	_cup = cup
	_sounds = sounds


## Follows the game `rules` (a new one each game): resets the launcher and the cup for it.
func bind(rules: PachinkoRules) -> void:
	_rules = rules
	rules.cup_changed.connect(_on_cup_changed)
	rules.power_changed.connect(_on_power_changed)
	rules.handle.changed.connect(_launcher.set_handle)
	rules.ball_loaded.connect(_on_loaded_changed)
	rules.ball_launched.connect(_on_ball_launched)
	rules.ball_won.connect(_on_ball_won)
	rules.ball_drained.connect(_on_ball_drained)
	rules.ball_returned.connect(_on_ball_returned)
	rules.world.pin_hit.connect(_on_pin_hit)
	rules.world.ring_hit.connect(_on_ring_hit)
	rules.bonus.jackpot_round_started.connect(_on_round_started)
	rules.bonus.jackpot_ended.connect(_on_jackpot_ended)
	rules.bonus.tulip_changed.connect(_on_tulip_changed)
	_open_tulips.clear()
	_launcher.set_aim_band(Vector2i.ZERO)
	# the balls the game starts with, behind the card too (it read 0 there)
	_cup.set_count(rules.level.cup_start_balls)
	_launcher.set_power(0.0, 0.0)
	paying = PayingStrengths.new()
	_launcher.set_paying(paying)
	_launcher.set_loaded(false)
	_launcher.set_handle(false, rules.handle.power)


# While a jackpot's rounds last the launcher shows where the attacker is fed (trial 5: once
# a stream paid there was little to decide), and while a tulip is open where it is reached
# (trial 7: there was still little to decide).
func _on_round_started(_round: int, _rounds: int) -> void:
	_show_aim()


func _on_jackpot_ended(_paid: int) -> void:
	_show_aim()


func _on_tulip_changed(index: int, open: bool) -> void:
	_open_tulips.erase(index)
	if open:
		_open_tulips.append(index)
	_show_aim()


func _show_aim() -> void:
	var aim := TulipBands.aim(_rules.level, _rules.bonus.rounds.active(), _open_tulips)
	var band: Vector2i = aim["band"]
	var words: String = aim["words"]
	_launcher.set_aim_band(band, words)


# The cup shows every ball still to shoot: the cup's and the one in the launcher.
func _on_cup_changed(_count: int) -> void:
	_cup.set_count(_rules.balls_to_shoot)


func _on_power_changed(power: float) -> void:
	_launcher.set_power(power, LaunchPower.flipper_degrees(_rules.power))


func _on_loaded_changed() -> void:
	_launcher.set_loaded(true)


func _on_ball_launched(id: int, power: float, _speed: float) -> void:
	paying.note_launch(id, power)
	_launcher.set_loaded(_rules.loaded)
	_cup.set_count(_rules.balls_to_shoot)
	if not _rules.handle.held:
		_launcher.set_last_shot(power)  # the handle's own dial keeps its strength
	_sounds.play(SoundBank.LAUNCH, lerpf(-8.0, 0.0, power / 100.0), lerpf(0.9, 1.15, power / 100.0))


func _on_ball_won(id: int, pocket: int, payout: int, at: Vector2) -> void:
	paying.note_paid(id, payout)
	_launcher.queue_redraw()
	_board_view.pockets.celebrate(pocket)
	_board_view.effects.pocket_win(at, payout)
	_cup.pour(payout)
	_sounds.play(SoundBank.POCKET_WIN)
	_launcher.set_loaded(_rules.loaded)


func _on_ball_drained(_id: int) -> void:
	_board_view.gutter.flash()
	_sounds.play(SoundBank.DRAIN, -6.0)


func _on_ball_returned(_id: int) -> void:
	var at := LaunchRail.return_zone_center(_rules.level)
	_board_view.effects.note(at + Vector2(-40, 0), "back to tray", Color("bfe3ff"))
	_sounds.play(SoundBank.BALL_RETURN, -4.0)
	_launcher.set_loaded(_rules.loaded)


func _on_pin_hit(_ball: int, _pin: int, speed: float) -> void:
	var tick := JuiceView.pin_sound(_rules.bonus)
	_sounds.play_impact(tick, speed, TICK_MIN_SPEED, TICK_MAX_SPEED)


func _on_ring_hit(_ball: int, speed: float) -> void:
	_sounds.play_impact(SoundBank.WALL_THUD, speed, TICK_MIN_SPEED * 2.0, TICK_MAX_SPEED * 1.5)
