extends RefCounted
## The bonus layer's shots on the Fever board: "pachinko_bonus" the reels turning (one
## landed, two rolling), "pachinko_reach" a reach on centre stage (the last reel slowing),
## "pachinko_jackpot" the jackpot moment with the attacker open, "pachinko_round" a later
## round of the jackpot, and "pachinko_jackpot_end" the summary card once a jackpot's last
## round is over (that jackpot given by setting the reels to three alike after 20 s of
## play, as tools/jackpot_sample.gd does: a natural one is rare), and "pachinko_house" the
## house's jackpot on a fresh save after its shots (announced as any jackpot,
## HouseJackpot).
## Each opens the game as the level select does and plays the screen's own rules forward at
## 60 fps until the moment comes; nothing else is faked (the views that ease in are given
## the real seconds they would have had on screen).

const ShotCapture := preload("res://tools/shots/shot_capture.gd")
const ScreenOpener := preload("res://tools/shots/screen_opener.gd")
const SaveData := preload("res://scripts/app/save_data.gd")
const GAME_SCENE := "res://scenes/pachinko/pachinko_game.tscn"
const BOARD := "res://levels/pachinko/fever.board"
## The shots this file takes, in order.
const NAMES: Array[String] = [
	"pachinko_bonus",
	"pachinko_reach",
	"pachinko_jackpot",
	"pachinko_round",
	"pachinko_jackpot_end",
	"pachinko_house",
]
const FRAME := 1.0 / 60.0
## Game seconds a shot may play before it gives up (90 minutes: with rules 5's one jackpot in
## 81 spins, about 2.6 an hour at this pace, 40 minutes went by without one about one run in
## six).
const LIMIT := 5400.0


## Opens the game on Fever, plays into the moment of `shot_name` and saves it.
static func take(tree: SceneTree, shot_name: String) -> Error:
	if not shot_name in NAMES:
		printerr("shots: bonus_shots has no shot '%s'" % shot_name)
		return ERR_INVALID_PARAMETER
	var kept_save := App.save_data
	if shot_name == "pachinko_house":  # a new player: a fresh save (in memory, never written)
		App.save_data = SaveData.new()
		App.house_jackpots = true
	var game := await ScreenOpener.open(
		tree, App.start_game.bind(BoardLevel.PACHINKO_NAME, BOARD), GAME_SCENE
	)
	App.house_jackpots = false
	App.save_data = kept_save
	if game == null:
		return ERR_CANT_OPEN
	var rules := (game as PachinkoGame).rules
	if rules == null:
		printerr("shots: %s: the game has no rules (the board did not load)" % shot_name)
		return ERR_CANT_OPEN
	if shot_name == "pachinko_house":  # the house waits for its shots: these are fired
		rules.ledger.shots = HouseJackpot.HOUSE_AFTER_SHOTS
	if shot_name == "pachinko_jackpot_end":
		_play_for(rules, 20.0)
		rules.bonus.reels.start(PackedInt32Array([2, 2, 2]), 9)
	var moments := {
		"pachinko_bonus": _spinning,
		"pachinko_reach": _mid_reach,
		"pachinko_jackpot": _jackpot,
		"pachinko_round": _third_round,
		"pachinko_jackpot_end": _jackpot_over,
		"pachinko_house": _jackpot,
	}
	if not _play_until(rules, moments[shot_name]):
		printerr("shots: %s: the moment did not come in %d s of play" % [shot_name, LIMIT])
		return FAILED
	var bonus_view := (game as PachinkoGame).bonus_view()
	# The balls paid in those minutes of play have landed in the cup by now on screen.
	var cup := (game as PachinkoGame).cup
	for frame in 20000:
		if cup.pouring() == 0:
			break
		cup._process(FRAME)
	if shot_name == "pachinko_jackpot" or shot_name == "pachinko_house":
		_play_for(rules, 0.3)  # the banner at its height, balls heading for the open lid
		# after the reach stage's moment of three alike has gone, as on screen (the banner
		# waits for it: one announcement at a time)
		bonus_view.stage._process(ReachStage.HOLD_JACKPOT + 0.01)
		bonus_view.stage._process(ReachStage.GROW_SECONDS + 0.01)
		bonus_view.banner._process(maxf(-bonus_view.banner._age, 0.0) + 0.3)
	if shot_name == "pachinko_round":
		_play_for(rules, 0.5)
		bonus_view.banner._process(0.5)
	if shot_name == "pachinko_jackpot_end":
		# the summary waits for the last round's balls to land (JackpotSettle)
		for frame in 1200:
			if bonus_view.banner.caption().contains("JACKPOT OVER"):
				break
			rules.advance(FRAME)
		bonus_view.banner._process(1.0)
	if shot_name == "pachinko_reach":
		bonus_view.stage._process(1.0)  # the stage has come in
	return await ShotCapture.save(tree.root, ShotCapture.path_for(shot_name))


# The first reel has landed and the others still turn.
static func _spinning(rules: PachinkoRules) -> bool:
	return rules.bonus.reels.stopped == 1


static func _jackpot(rules: PachinkoRules) -> bool:
	return rules.bonus.any_attacker_open()


# Half way through a reach: the last reel has slowed a good deal.
static func _mid_reach(rules: PachinkoRules) -> bool:
	return rules.bonus.reels.reach_progress() >= 0.5


# The jackpot given at the start has played its last round.
static func _jackpot_over(rules: PachinkoRules) -> bool:
	return rules.bonus.counters().get("jackpots_finished", 0) > 0


static func _third_round(rules: PachinkoRules) -> bool:
	return rules.bonus.rounds.current_round == 3 and rules.bonus.any_attacker_open()


static func _play_until(rules: PachinkoRules, moment: Callable) -> bool:
	var frame := 0
	while frame < int(LIMIT / FRAME):
		_tick(rules, frame)
		frame += 1
		if moment.call(rules):
			return true
	return false


static func _play_for(rules: PachinkoRules, seconds: float) -> void:
	for frame in int(seconds / FRAME):
		_tick(rules, frame)


# One frame of steady play: a new game when one ends, a shot every 0.6 s.
static func _tick(rules: PachinkoRules, frame: int) -> void:
	if rules.state != PachinkoRules.State.PLAYING:
		rules.start_game()
	if rules.loaded and frame % 45 == 0:
		# Powers spread like a player's (a golden-ratio walk over 5..100).
		rules.fire(5.0 + fmod(float(frame / 45) * 61.8034, 95.0))
	rules.advance(FRAME)
