class_name JuiceView
extends Node
## Wires the juice to a game, each effect its own node: the slow motion of the last balls
## and its spotlight, the jackpot's camera nudge and light sweep, pockets' rim pins lighting
## on a catch, the fever round's beacon over the open attacker and its countdown beeps.
## The game asks `time_scale()` once a frame for its clock; everything else follows the
## rules' and the bonus machine's signals.

var slow_motion := SlowMotion.new()
var focus := SlowMotionFocus.new()
var nudge := CameraNudge.new()
var sweep := LightSweep.new()
var catch_lights := CatchLights.new()
var countdown := FeverCountdown.new()
var beacon := AttackerBeacon.new()

var _board_view: BoardView
var _sounds: SoundBank


## Adds the effects to the game: the open attacker's beacon under `board_view`'s balls,
## the slow motion's spotlight and the sweep over them, the rest as children of this node;
## sounds go to `sounds`.
func attach(board_view: BoardView, sounds: SoundBank) -> void:
	_board_view = board_view
	_sounds = sounds
	for effect: Node in [slow_motion, nudge, catch_lights, countdown]:
		add_child(effect)
	beacon.name = "AttackerBeacon"
	board_view.add_child(beacon)
	board_view.move_child(beacon, board_view.balls.get_index())
	focus.name = "SlowMotionFocus"
	board_view.add_child(focus)
	sweep.name = "LightSweep"
	board_view.add_child(sweep)
	nudge.attach(board_view, sounds)
	slow_motion.set_sounds(sounds)
	SoundBank.warm(JuiceRecipes.names())


## Follows the game of `rules` (a new game's rules each time); call after the board view
## is bound to them.
func bind(rules: PachinkoRules) -> void:
	var lights := _board_view.pin_lights()
	nudge.enabled = App.settings.screen_shake
	slow_motion.bind(rules)
	focus.bind(slow_motion, rules.world)
	sweep.bind(rules.level, lights, _sounds)
	catch_lights.bind(rules, lights)
	countdown.bind(rules.bonus, rules.level.bonus_pockets.size(), _sounds)
	beacon.bind(rules.level, rules.bonus)
	rules.bonus.reels_finished.connect(_on_reels_finished)


## The pin tick for a strike now: brighter while `machine` has an attacker open (fever).
static func pin_sound(machine: BonusMachine) -> StringName:
	return SoundBank.PIN_FEVER if machine.any_attacker_open() else SoundBank.PIN_TICK


## The factor for this frame's game time (below 1 in slow motion), `real_delta` seconds
## after the last frame.
func time_scale(rules: PachinkoRules, real_delta: float) -> float:
	return slow_motion.update(rules, real_delta)


func _on_reels_finished(_result: PackedInt32Array, jackpot: bool) -> void:
	if jackpot:
		nudge.enabled = App.settings.screen_shake
		nudge.kick()
		sweep.start()
