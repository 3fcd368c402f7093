extends GutTest
## The pachinko rules card after a blind player trial: every board's card fits the board's
## area at 1280 × 720 and 900 × 700 (Fever's ran off the window); the full card comes the
## first time a board is played, later games and R start at once under a one-line reminder;
## the cup behind the card shows the balls the game starts with (it read 0); and a start key
## held as the game ends (the stream key) leaves the game-over summary up until let go.

const GAME := preload("res://scenes/pachinko/pachinko_game.tscn")
const SaveData := preload("res://scripts/app/save_data.gd")
const StretchedWindow := preload("res://tests/integration/stretched_window.gd")
const BOARDS: Array[String] = ["classic", "windmills", "tulips", "fever", "hanami"]
const SIZES: Array[Vector2i] = [Vector2i(1280, 720), Vector2i(900, 700)]

var _kept_save: SaveData
var _kept_skip := false


func before_each() -> void:
	_kept_save = App.save_data
	_kept_skip = App.skip_seen_rules_cards
	App.save_data = SaveData.new()  # in memory only: never written
	App.request_board("pachinko", "res://levels/pachinko/classic.board")


func after_each() -> void:
	Input.parse_input_event(_key(&"launch_handle", false))
	App.save_data = _kept_save
	App.skip_seen_rules_cards = _kept_skip


## The rect `control` covers on its canvas, its scale included.
static func _drawn_rect(control: Control) -> Rect2:
	var xf := control.get_global_transform()
	return Rect2(xf.origin, xf.basis_xform(control.size))


func _key(action: StringName, pressed: bool) -> InputEventKey:
	var key := InputEventKey.new()
	for event in InputMap.action_get_events(action):
		if event is InputEventKey:
			key.physical_keycode = (event as InputEventKey).physical_keycode
			key.keycode = (event as InputEventKey).keycode
			break
	key.pressed = pressed
	return key


func test_every_boards_card_fits_its_area_in_both_windows() -> void:
	for board in BOARDS:
		App.request_board("pachinko", "res://levels/pachinko/%s.board" % board)
		for size in SIZES:
			var game := await StretchedWindow.open(self, GAME, size, 4) as PachinkoGame
			assert_true(game.instructions.visible, "%s %s: the card is up" % [board, size])
			var card := _drawn_rect(game.instructions.card())
			var area := _drawn_rect(game.instructions).grow(0.5)
			var view := game.get_viewport_rect().grow(0.5)
			assert_true(
				area.encloses(card), "%s %s: card %s in the area %s" % [board, size, card, area]
			)
			assert_true(
				view.encloses(card), "%s %s: card %s on screen %s" % [board, size, card, view]
			)
			game.free()  # before its window


func test_the_full_card_comes_once_then_a_reminder_that_never_blocks() -> void:
	App.skip_seen_rules_cards = true
	var game := GAME.instantiate() as PachinkoGame
	add_child_autofree(game)
	await wait_process_frames(1)
	assert_eq(game.rules.state, PachinkoRules.State.INSTRUCTIONS, "a new player gets the card")
	assert_false(game.reminder().visible)
	game.instructions._process(1.0)
	game.instructions.play_requested.emit()
	assert_eq(game.rules.state, PachinkoRules.State.PLAYING)
	assert_true(App.save_data.has_seen_pachinko_rules(game.rules.level.board_id), "remembered")
	game.restart()  # R
	assert_eq(game.rules.state, PachinkoRules.State.PLAYING, "after R the game is on at once")
	assert_false(game.instructions.visible, "no card")
	assert_true(game.reminder().visible, "a one-line reminder instead")
	assert_string_contains(game.reminder().text(), "Shoot:")
	assert_eq(game.reminder().mouse_filter, Control.MOUSE_FILTER_IGNORE, "never in the way")
	var again := GAME.instantiate() as PachinkoGame
	add_child_autofree(again)
	await wait_process_frames(1)
	assert_eq(again.rules.state, PachinkoRules.State.PLAYING, "a later game on the board too")
	assert_true(again.reminder().visible)


func test_the_cup_behind_the_card_shows_the_starting_balls() -> void:
	var game := GAME.instantiate() as PachinkoGame
	add_child_autofree(game)
	await wait_process_frames(1)
	assert_true(game.instructions.visible)
	assert_eq(game.cup.count(), game.rules.level.cup_start_balls)


# A play trial streamed with Shift held as the last ball came down: the summary was gone
# before it could be read. A start key held as the card comes up is ignored until let go.
func test_a_start_key_held_as_the_game_ends_leaves_the_summary_up() -> void:
	var game := GAME.instantiate() as PachinkoGame
	add_child_autofree(game)
	await wait_process_frames(1)
	var rules := game.rules
	rules.start_game()
	Input.parse_input_event(_key(&"launch_handle", true))
	await wait_process_frames(1)
	rules.state = PachinkoRules.State.GAME_OVER
	rules.game_ended.emit(rules.stats(true))
	assert_true(game.instructions.visible, "the summary is up")
	game.instructions._process(1.0)  # read for a second
	# the held key's repeats (Xvfb's arrive as presses)
	game._unhandled_input(_key(&"launch_handle", true))
	assert_eq(rules.state, PachinkoRules.State.GAME_OVER, "the held key leaves the summary up")
	assert_true(game.instructions.visible)
	Input.parse_input_event(_key(&"launch_handle", false))
	game._unhandled_input(_key(&"launch_handle", false))
	game._unhandled_input(_key(&"launch_handle", true))
	assert_eq(rules.state, PachinkoRules.State.PLAYING, "let go and pressed again, it plays")
