extends RefCounted
## A pocket's and the pins' flash on each machine ("flash_classic", "flash_windmills", ...):
## a board opened as the level select does, a stream from the handle played at 60 fps
## through the screen's own rules until a pocket pays, then the picture a frame later, so it
## shows the balls, their highlight and contact shadow, the lit pins and the pocket's flash
## on every fascia.

const ShotCapture := preload("res://tools/shots/shot_capture.gd")
const ScreenOpener := preload("res://tools/shots/screen_opener.gd")
const GAME_SCENE := "res://scenes/pachinko/pachinko_game.tscn"
## The shots this file takes, in order: "flash_" + the board file's name.
const NAMES: Array[String] = [
	"flash_classic", "flash_windmills", "flash_tulips", "flash_fever", "flash_hanami"
]
const FRAME := 1.0 / 60.0
## The longest the stream plays waiting for a pocket to pay, seconds.
const MAX_SECONDS := 60
## Handle strengths tried in turn; each board has a pocket one of them feeds.
const POWERS: Array[float] = [35.0, 55.0, 75.0]


## Opens the board of `shot_name`, streams balls until a pocket pays and saves the picture.
## OK or the reason it failed.
static func take(tree: SceneTree, shot_name: String) -> Error:
	if not shot_name in NAMES:
		printerr("shots: flash_shots has no shot '%s'" % shot_name)
		return ERR_INVALID_PARAMETER
	var board := "res://levels/pachinko/%s.board" % shot_name.trim_prefix("flash_")
	var game := await ScreenOpener.open(
		tree, App.start_game.bind(BoardLevel.PACHINKO_NAME, board), GAME_SCENE
	)
	if game == null:
		return ERR_CANT_OPEN
	var rules := (game as PachinkoGame).rules
	if rules == null:
		printerr("shots: %s: the game has no rules (the board did not load)" % shot_name)
		return ERR_CANT_OPEN
	var paid := [false]
	rules.ball_won.connect(func(_b: int, _p: int, _n: int, _at: Vector2) -> void: paid[0] = true)
	rules.start_game()
	rules.handle.grip()
	var frames_per_power := ceili(MAX_SECONDS / FRAME / POWERS.size())
	for frame in int(MAX_SECONDS / FRAME):
		if frame % frames_per_power == 0:
			var which := floori(float(frame) / frames_per_power)
			rules.handle.set_power(POWERS[mini(which, POWERS.size() - 1)])
		rules.advance(FRAME)
		if paid[0]:
			break
	if not paid[0]:
		printerr("shots: %s: no pocket paid in %d s" % [shot_name, MAX_SECONDS])
	# the scene's own frames play on while the picture settles: one is enough
	return await ShotCapture.save(tree.root, ShotCapture.path_for(shot_name), 1)
