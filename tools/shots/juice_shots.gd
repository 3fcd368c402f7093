extends RefCounted
## The pachinko's juice caught mid-effect on the Fever board: "pachinko_juice_sweep" the
## jackpot's light sweep halfway across the field (the board nudged), "pachinko_juice_fever"
## the fever round a moment later, "pachinko_juice_slowmo" a last ball in slow motion as it
## drops toward a pocket. Each plays the screen's own rules forward at 60 fps until the
## moment is near (nothing is faked), then lets the game run real frames into it.

const ShotCapture := preload("res://tools/shots/shot_capture.gd")
const ScreenOpener := preload("res://tools/shots/screen_opener.gd")
const GAME_SCENE := "res://scenes/pachinko/pachinko_game.tscn"
const BOARD := "res://levels/pachinko/fever.board"
## The shots this file takes, in order.
const NAMES: Array[String] = [
	"pachinko_juice_sweep", "pachinko_juice_fever", "pachinko_juice_slowmo"
]
const FRAME := 1.0 / 60.0
## Game seconds a shot may play before it gives up.
const LIMIT := 2400.0
## Real seconds into an effect the picture is taken.
const INTO_SWEEP := 0.4
const INTO_FEVER := 2.5
const INTO_SLOW := 0.3


## Opens the game on Fever, plays into the moment of `shot_name` and saves it.
static func take(tree: SceneTree, shot_name: String) -> Error:
	if not shot_name in NAMES:
		printerr("shots: juice_shots has no shot '%s'" % shot_name)
		return ERR_INVALID_PARAMETER
	var game := await ScreenOpener.open(
		tree, App.start_game.bind(BoardLevel.PACHINKO_NAME, BOARD), GAME_SCENE
	)
	if game == null or (game as PachinkoGame).rules == null:
		printerr("shots: %s: the game did not open with a board" % shot_name)
		return ERR_CANT_OPEN
	var rules := (game as PachinkoGame).rules
	var moment := _slow_moment(rules) if shot_name == "pachinko_juice_slowmo" else _jackpot_near
	if not _play_until(rules, moment, shot_name != "pachinko_juice_slowmo"):
		printerr("shots: %s: the moment did not come in %d s of play" % [shot_name, LIMIT])
		return FAILED
	var wait := INTO_SWEEP
	if shot_name == "pachinko_juice_fever":
		wait = INTO_FEVER
	elif shot_name == "pachinko_juice_slowmo":
		wait = INTO_SLOW
	await tree.create_timer(wait).timeout
	return await ShotCapture.save(tree.root, ShotCapture.path_for(shot_name), 1)


# The reels have just lined up: the juice started with them, the game's frames run it.
static func _jackpot_near(rules: PachinkoRules) -> bool:
	return rules.bonus.any_attacker_open()


# A game in its last balls with a ball about to drop into a pocket.
static func _slow_moment(rules: PachinkoRules) -> Callable:
	var approach := PocketApproach.new(rules.level, rules.world.tuning.gravity)
	return func(live: PachinkoRules) -> bool:
		if not SlowMotion.in_last_balls(live):
			return false
		return approach.find_ball(live.world, live.bonus) >= 0


static func _play_until(rules: PachinkoRules, moment: Callable, keep_firing: bool) -> bool:
	var frame := 0
	while frame < int(LIMIT / FRAME):
		_tick(rules, frame, keep_firing)
		frame += 1
		if moment.call(rules):
			return true
	return false


# One frame of steady play: a new game when one ends, a shot every 0.6 s (the slow-motion
# shot fires the whole cup fast, so games end often).
static func _tick(rules: PachinkoRules, frame: int, keep_firing: bool) -> void:
	if rules.state != PachinkoRules.State.PLAYING:
		rules.start_game()
	var every := 45 if keep_firing else 12
	if rules.loaded and frame % every == 0:
		# Powers spread like a player's (a golden-ratio walk over 5..100).
		rules.fire(5.0 + fmod(float(frame / every) * 61.8034, 95.0))
	rules.advance(FRAME)
