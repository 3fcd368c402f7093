extends RefCounted
## The five machines, one shot each ("machine_classic", "machine_windmills", ...): a board
## opened as the level select does (App.start_game), a stream from the held handle played
## forward for a few seconds at 60 fps through the screen's own rules, so each picture shows
## the machine's art, palette and name plate with balls in flight.

const ShotCapture := preload("res://tools/shots/shot_capture.gd")
const ScreenOpener := preload("res://tools/shots/screen_opener.gd")
const GAME_SCENE := "res://scenes/pachinko/pachinko_game.tscn"
## The shots this file takes, in order: "machine_" + the board file's name.
const NAMES: Array[String] = [
	"machine_classic", "machine_windmills", "machine_tulips", "machine_fever", "machine_hanami"
]
const FRAME := 1.0 / 60.0
## Seconds of streaming before the picture.
const PLAY_SECONDS := 4


## Opens the board of `shot_name`, plays a stream into it and saves the picture. OK or the
## reason it failed.
static func take(tree: SceneTree, shot_name: String) -> Error:
	if not shot_name in NAMES:
		printerr("shots: machine_shots has no shot '%s'" % shot_name)
		return ERR_INVALID_PARAMETER
	var board := "res://levels/pachinko/%s.board" % shot_name.trim_prefix("machine_")
	var game := await ScreenOpener.open(
		tree, App.start_game.bind(BoardLevel.PACHINKO_NAME, board), GAME_SCENE
	)
	if game == null:
		return ERR_CANT_OPEN
	var rules := (game as PachinkoGame).rules
	if rules == null:
		printerr("shots: %s: the game has no rules (the board did not load)" % shot_name)
		return ERR_CANT_OPEN
	rules.start_game()
	rules.handle.set_power(70.0)
	rules.handle.grip()
	for frame in 60 * PLAY_SECONDS:
		rules.advance(FRAME)
	return await ShotCapture.save(tree.root, ShotCapture.path_for(shot_name))
