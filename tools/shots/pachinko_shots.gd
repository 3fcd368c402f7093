extends RefCounted
## The pachinko shots: "pachinko_start" the instructions, "pachinko_play" a stream
## from the held handle with struck pins lit and the flipper drawn back, "pachinko_aim" the
## flipper drawn back after a first shot (the flight shown on the board, the last shot's
## mark on the power bar), "pachinko_win" the moment a pocket pays out, "pachinko_over"
## game over, "pachinko_start_fever" Fever's card (the tallest), "pachinko_reminder" a later
## game's one-line reminder, "pachinko_paying" Fever streamed at three strengths, the power
## bar lit green by the strengths that paid, "pachinko_restart_ask" R's question after a
## few seconds of streaming, "pachinko_cleared" the win card once the tray reached its
## goal. Each opens the game as the level select does
## (App.start_game) and plays the screen's own rules (PachinkoGame.rules) forward at 60 fps;
## nothing is faked.

const ShotCapture := preload("res://tools/shots/shot_capture.gd")
const ScreenOpener := preload("res://tools/shots/screen_opener.gd")
const GAME_SCENE := "res://scenes/pachinko/pachinko_game.tscn"
const BOARD := "res://levels/pachinko/classic.board"
## The shots this file takes, in order.
const NAMES: Array[String] = [
	"pachinko_start",
	"pachinko_play",
	"pachinko_aim",
	"pachinko_win",
	"pachinko_over",
	"pachinko_start_fever",
	"pachinko_reminder",
	"pachinko_paying",
	"pachinko_restart_ask",
	"pachinko_cleared",
]
const FEVER := "res://levels/pachinko/fever.board"
const FRAME := 1.0 / 60.0


## Opens the game, plays it into the moment of `shot_name` and saves it. OK or the reason
## it failed.
static func take(tree: SceneTree, shot_name: String) -> Error:
	if not shot_name in NAMES:
		printerr("shots: pachinko_shots has no shot '%s'" % shot_name)
		return ERR_INVALID_PARAMETER
	var board := FEVER if shot_name in ["pachinko_start_fever", "pachinko_paying"] else BOARD
	if shot_name == "pachinko_reminder":
		App.note_pachinko_rules_seen(BoardLoader.load_board(BOARD).level.board_id)
		App.skip_seen_rules_cards = true
	var game := await ScreenOpener.open(
		tree, App.start_game.bind(BoardLevel.PACHINKO_NAME, board), GAME_SCENE
	)
	App.skip_seen_rules_cards = false
	if game == null:
		return ERR_CANT_OPEN
	var rules := (game as PachinkoGame).rules
	if rules == null:
		printerr("shots: %s: the game has no rules (the board did not load)" % shot_name)
		return ERR_CANT_OPEN
	match shot_name:
		"pachinko_play":
			_play(rules, game.get_node("BoardView/PinLights"))
			game.get_node("Hud/Column/Info/Numbers/Stats").call("show_stats", rules.stats())
		"pachinko_aim":
			(game as PachinkoGame).board_view.aim_preview().preview()  # measured by now
			rules.start_game()
			rules.begin_charge()
			rules.set_power(80.0)
			rules.release()
			for frame in 60 * 2:
				rules.advance(FRAME)
			rules.begin_charge()
			rules.set_power(52.0)
			(game as PachinkoGame).board_view.aim_preview()._process(0.5)
		"pachinko_paying":
			rules.start_game()
			rules.handle.grip()
			for strength: float in [30.0, 55.0, 72.0]:
				rules.handle.set_power(strength)
				for frame in 60 * 30:
					rules.advance(FRAME)
			rules.handle.let_go()
		"pachinko_win":
			if not _win(rules):
				printerr("shots: pachinko_win: no pocket paid out in 90 s of play")
				return FAILED
		"pachinko_restart_ask":
			rules.start_game()
			rules.handle.grip()
			for i in 240:
				rules.advance(FRAME)
				await tree.process_frame
			rules.handle.let_go()
			var press := InputEventAction.new()
			press.action = &"game_restart"
			press.pressed = true
			Input.parse_input_event(press)
			for i in 6:
				await tree.process_frame
		"pachinko_cleared":
			rules.start_game()
			for i in 120:
				rules.advance(FRAME)
				await tree.process_frame
			# the tray's last balls come as a payout does
			rules.cup += PachinkoGoals.tray_target(rules.level) - rules.balls_to_shoot
			rules.cup_changed.emit(rules.cup)
			for i in 10:
				await tree.process_frame
		"pachinko_over":
			if not _over(rules):
				printerr("shots: pachinko_over: the game was still on after 240 s of play")
				return FAILED
	return await ShotCapture.save(tree.root, ShotCapture.path_for(shot_name))


static func _play(rules: PachinkoRules, pin_lights: Node) -> void:
	rules.start_game()
	rules.handle.set_power(72.0)
	rules.handle.grip()
	for frame in 60 * 5:
		rules.advance(FRAME)
		# The lights fade per frame; played forward here, they need the frames too.
		pin_lights._process(FRAME)
	# Grab the flipper and draw it back, as a held mouse button does.
	rules.press_flipper(Vector2(0, 100))
	rules.drag_to(Vector2(0, 35))


# True once a pocket paid out (the win effect is then on screen).
static func _win(rules: PachinkoRules) -> bool:
	rules.start_game()
	var won := [false]
	var mark := func(_id: int, _pocket: int, _payout: int, _at: Vector2) -> void: won[0] = true
	rules.ball_won.connect(mark)
	for frame in 60 * 90:
		if rules.state != PachinkoRules.State.PLAYING:
			rules.start_game()
		if rules.loaded and frame % 9 == 0:
			rules.fire(30.0 + float(frame * 37 % 70))
		rules.advance(FRAME)
		if won[0]:
			break
	rules.ball_won.disconnect(mark)
	return won[0]


# True once the cup ran dry and the game ended (the summary is then on screen).
static func _over(rules: PachinkoRules) -> bool:
	rules.start_game()
	for frame in 60 * 240:
		if rules.state == PachinkoRules.State.GAME_OVER:
			break
		# Lone weak shots, which seldom pay: the cup runs dry in a minute or two.
		if rules.loaded and frame % 20 == 0:
			rules.fire(20.0 + float(frame * 53 % 10))
		rules.advance(FRAME)
	return rules.state == PachinkoRules.State.GAME_OVER
