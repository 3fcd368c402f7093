class_name BonusView
extends Node
## Wires the bonus layer's pictures and sounds to a game: puts the bonus art and the reels
## and the reach stage into the board view under the balls and the jackpot's moments over
## them, answers the BonusMachine's signals (lamps, reel sounds, the reach's rising tone,
## the jackpot's fanfare and rounds, tulips opening), and slows the game's clock for a
## reach (`time_scale`).

## The z of the reach stage, and one above it the jackpot banner's: over the balls and the
## aim's dots.
const MOMENT_Z := 90
## Seconds between the reach stage's going and the jackpot banner's coming.
const STAGE_CLEAR_SECONDS := 0.1

var art := BonusArt.new()
var reels := ReelDisplay.new()
var banner := JackpotBanner.new()
var fever := FeverGlow.new()
var stage := ReachStage.new()
var slow_motion := ReachSlowMotion.new()

var _sounds: SoundBank
var _rules: PachinkoRules
## The rounds of the jackpot under way that are over (its summary says how many were played).
var _rounds_played := 0
# When a jackpot's last balls have landed: its summary counts them (trial 6).
var _settle: JackpotSettle
# True from a jackpot again's announcement to its round 1 (which then has its own moment).
var _again := false
# What the last jackpot paid (-1: none yet this game), said by a jackpot again's banner.
var _last_paid := -1


## The sound bank the bonus moments play on (a test may hand it a recording one).
func use_sounds(sounds: SoundBank) -> void:
	_sounds = sounds


## Adds the layers to `board_view` (a Node2D with a "Balls" child) and keeps `sounds`.
func attach(board_view: Node2D, sounds: SoundBank) -> void:
	_sounds = sounds
	var balls := board_view.get_node_or_null("Balls")
	var under := balls.get_index() if balls != null else board_view.get_child_count()
	board_view.add_child(art)
	board_view.move_child(art, under)
	board_view.add_child(reels)
	board_view.move_child(reels, under + 1)
	board_view.add_child(fever)
	board_view.move_child(fever, under + 2)
	# the reach's stage over the balls (trial 7: balls crossed its big reels); it keeps to
	# the top of the board, so the balls falling through the pins stay in sight
	board_view.add_child(stage)
	board_view.move_child(stage, under + 3)
	stage.z_index = MOMENT_Z
	board_view.add_child(banner)
	# the jackpot's words over everything on the board (balls, the aim's dots drawn after them)
	banner.z_index = MOMENT_Z + 1
	(
		SoundBank
		. warm(
			[
				SoundBank.REEL_STOP,
				SoundBank.TULIP_OPEN,
				SoundBank.START_CATCH,
				SoundBank.FEVER_END,
				SoundBank.REACH_RISE,
				SoundBank.JACKPOT_FANFARE,
				SoundBank.ROUND_BELL,
			]
		)
	)


## True while a big moment holds the board: the reach stage or a jackpot, round or summary
## banner is up (the aim's dots are hidden meanwhile).
func holds_the_stage() -> bool:
	return stage.is_on_stage() or banner.is_showing()


## True when the aim's flight must be hidden now, the player `aiming` or not: a banner hides
## it, but the reach stage fades for an aim instead (trial 9 fired blind under the reels).
func holds_the_aim(aiming: bool) -> bool:
	stage.see_through = aiming
	return banner.is_showing() or (stage.is_on_stage() and not aiming)


## Shows the bonus layer of `rules` (a new game's rules each time).
func bind(rules: PachinkoRules) -> void:
	_rules = rules
	var machine := rules.bonus
	art.bind(rules.level, machine)
	reels.bind(rules.level, machine)
	fever.bind(rules.level, machine)
	fever.stage = stage  # its caption keeps clear of the big reels
	fever.banner = banner  # and waits while a banner says the round
	stage.bind(rules.level, machine)
	slow_motion.reset()
	machine.start_caught.connect(_on_start_caught)
	machine.reel_stopped.connect(_on_reel_stopped)
	machine.reels_finished.connect(_on_reels_finished)
	machine.attacker_changed.connect(_on_attacker_changed)
	machine.tulip_changed.connect(_on_tulip_changed)
	machine.reach_started.connect(_on_reach_started)
	machine.jackpot_round_started.connect(_on_round_started)
	machine.jackpot_round_ended.connect(_on_round_ended)
	machine.jackpot_ended.connect(_on_jackpot_ended)
	_again = false
	_last_paid = -1
	_settle = JackpotSettle.new(rules)
	_settle.settled.connect(_on_jackpot_settled)
	rules.ball_won.connect(_on_ball_won)
	HouseJackpot.offer(rules)


## The factor for the game's clock this frame of `real_delta` seconds: below 1 during a
## reach (ReachSlowMotion).
func time_scale(real_delta: float) -> float:
	return slow_motion.time_scale(_rules.bonus if _rules != null else null, real_delta)


func _on_ball_won(_id: int, pocket: int, _payout: int, _at: Vector2) -> void:
	art.flash(BonusGeometry.bonus_index(_rules.level, pocket))


func _on_start_caught(_index: int, _queued: int) -> void:
	_play(SoundBank.START_CATCH, -4.0)


func _on_reel_stopped(reel: int, _symbol: int) -> void:
	_play(SoundBank.REEL_STOP, -6.0, 1.0 + reel * 0.08)


func _on_reels_finished(_result: PackedInt32Array, jackpot: bool) -> void:
	if jackpot:
		var level := _rules.level
		var rounds := JackpotRounds.ROUNDS
		# the banner waits until the stage has gone: one announcement at a time (trial 7
		# read a fading "REACH!" and "444" under "ROUND 1 / 10")
		var delay := ReachStage.HOLD_JACKPOT + ReachStage.GROW_SECONDS + STAGE_CLEAR_SECONDS
		_again = _rules.bonus.rounds.announcing()
		if _again:  # its round 1 waits for this (trial 8: "JACKPOT OVER" over a running round)
			banner.show_again(level.ring_center, level.ring_radius, delay, _last_paid)
		else:
			banner.show_jackpot(level.ring_center, level.ring_radius, rounds, delay)
		_play(SoundBank.JACKPOT_FANFARE)


func _on_reach_started() -> void:
	_play(SoundBank.REACH_RISE, -3.0)


func _on_round_ended(round_number: int, _rounds: int) -> void:
	_rounds_played = round_number


func _on_round_started(round_number: int, rounds: int) -> void:
	# the first comes with the jackpot's own moment, but after a jackpot again's announcement
	if round_number > 1 or _again:
		_again = false
		banner.show_round(_rules.level.ring_center, _rules.level.ring_radius, round_number, rounds)
		_play(SoundBank.ROUND_BELL, -4.0)


func _on_jackpot_ended(paid: int) -> void:
	_last_paid = paid


# The summary waits for the last round's balls: its count then is the panel's; a jackpot
# again already on has said what the last one paid, and its own moment keeps the middle.
func _on_jackpot_settled(paid: int) -> void:
	if _rules.bonus.rounds.active():
		return
	var session_paid: int = _rules.stats(true).get("game_payouts", 0)
	var level := _rules.level
	banner.show_summary(level.ring_center, level.ring_radius, _rounds_played, paid, session_paid)
	_play(SoundBank.FEVER_END, -3.0)


func _on_attacker_changed(index: int, _open: bool) -> void:
	art.flash(index)


func _on_tulip_changed(index: int, open: bool) -> void:
	art.flash(index)
	if open:
		_play(SoundBank.TULIP_OPEN, -6.0)


func _play(sound: StringName, volume_db := 0.0, pitch := 1.0) -> void:
	if _sounds != null:
		_sounds.play(sound, volume_db, pitch)
