extends RefCounted
## The gold pins on every machine, three shots each: "gold_<board>_lit" the set lit while
## the handle is held at the chasing pilot's strength (the aim's rings on the gold pins it
## reaches), "gold_<board>_hit" a moment after a ball put one out (its burst and "+1"),
## "gold_<board>_prize" the set's prize announced as its last pin goes out. Each plays the
## screen's own rules forward with the gold-chasing pilot (GoldChaser) until the moment
## comes (nothing is faked), then lets the game run real frames into it.

const ShotCapture := preload("res://tools/shots/shot_capture.gd")
const ScreenOpener := preload("res://tools/shots/screen_opener.gd")
const GAME_SCENE := "res://scenes/pachinko/pachinko_game.tscn"
const BOARDS: Array[String] = ["classic", "windmills", "tulips", "fever", "hanami"]
## The shots this file takes, in order.
const NAMES: Array[String] = [
	"gold_classic_lit",
	"gold_classic_hit",
	"gold_classic_prize",
	"gold_windmills_lit",
	"gold_windmills_hit",
	"gold_windmills_prize",
	"gold_tulips_lit",
	"gold_tulips_hit",
	"gold_tulips_prize",
	"gold_fever_lit",
	"gold_fever_hit",
	"gold_fever_prize",
	"gold_hanami_lit",
	"gold_hanami_hit",
	"gold_hanami_prize",
]
const FRAME := 1.0 / 60.0
## Fast frames played between two real ones.
const CHUNK := 10

## Game seconds a shot may play before it gives up.
const LIMIT := 600.0
## Real seconds into the moment the picture is taken.
const INTO := {"lit": 0.5, "hit": 0.1, "prize": 0.15}

## The gold pins' state the pilot last aimed at (it aims again when it changes).
static var _aimed_at := -1


## Opens the board of `shot_name`, plays into its moment and saves the picture.
static func take(tree: SceneTree, shot_name: String) -> Error:
	if not shot_name in NAMES:
		printerr("shots: gold_shots has no shot '%s'" % shot_name)
		return ERR_INVALID_PARAMETER
	var parts := shot_name.split("_")
	var board := "res://levels/pachinko/%s.board" % parts[1]
	var game := await ScreenOpener.open(
		tree, App.start_game.bind(BoardLevel.PACHINKO_NAME, board), GAME_SCENE
	)
	if game == null or (game as PachinkoGame).rules == null:
		printerr("shots: %s: the game did not open with a board" % shot_name)
		return ERR_CANT_OPEN
	var rules := (game as PachinkoGame).rules
	rules.start_game()
	var moment := parts[2]
	var out := rules.gold.pins_out
	var sets := rules.gold.sets_cleared
	var frames := 0
	# fast play in chunks, a real frame between them, so the moment's effects start in a
	# frame of ordinary length (one long fast run would age them out in its first frame)
	while frames < int(LIMIT / FRAME):
		for i in CHUNK:
			_aim(rules)
			rules.advance(FRAME)
			frames += 1
			if _reached(moment, rules, out, sets, frames):
				break
		if _reached(moment, rules, out, sets, frames):
			break
		var card := game.get("_cleared_card") as Control
		if card != null and card.visible:
			card.call("dismiss")  # the machine's goal reached on the way would hide the moment
		await tree.process_frame
	await tree.create_timer(INTO[moment]).timeout
	return await ShotCapture.save(tree.root, ShotCapture.path_for(shot_name), 1)


static func _reached(
	moment: String, rules: PachinkoRules, out: int, sets: int, frames: int
) -> bool:
	match moment:
		"hit":
			return rules.gold.pins_out > out
		"prize":
			return rules.gold.sets_cleared > sets
	return frames >= 120


# The chasing pilot's handle, held; a game that ended is followed by the next.
static func _aim(rules: PachinkoRules) -> void:
	if rules.state != PachinkoRules.State.PLAYING:
		rules.start_game()
	if GoldChaser.aim_key(rules) != _aimed_at:
		_aimed_at = GoldChaser.aim_key(rules)
		rules.handle.set_power(GoldChaser.strength(rules))
	rules.handle.grip()
