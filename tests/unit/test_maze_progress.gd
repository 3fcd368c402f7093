extends GutTest
## Maze progression: boards open one after another in MazeProgress.ORDER (the settings can
## open them all), and the level select shows the locks and each board's medals.

const LevelSelectScene := preload("res://scenes/menu/level_select.tscn")
const ScratchSave := preload("res://tests/helpers/scratch_save.gd")
const SAVE := "user://test_maze_progress_save.cfg"
const SETTINGS := "user://test_maze_progress_settings.cfg"
const EMPTY_USER_ROOT := "user://test_maze_progress_no_boards"

var _real_save: RefCounted = null


func before_each() -> void:
	_real_save = ScratchSave.swap_in(SAVE)


func after_each() -> void:
	ScratchSave.restore(_real_save, SAVE)
	DirAccess.remove_absolute(SETTINGS)


func test_every_shipped_maze_is_in_the_order_once() -> void:
	var listed := BoardLoader.list_boards(BoardLevel.Kind.MAZE)
	assert_gte(listed.size(), 12, "twelve boards or more")
	for loaded in listed:
		assert_lt(MazeProgress.rank(loaded.level.board_id), MazeProgress.ORDER.size(), loaded.path)
	var sorted := MazeProgress.sorted(listed)
	assert_eq(sorted[0].level.board_id, MazeProgress.ORDER[0])
	assert_eq(sorted[-1].level.board_id, MazeProgress.ORDER[-1])


func test_locks_open_one_board_after_another() -> void:
	var ids: Array[String] = ["maze_garden", "maze_classic", "maze_cloister", "my_own"]
	assert_eq(MazeProgress.locks(ids, {}, false), [false, true, true, false] as Array[bool])
	var done := {"maze_garden": true}
	assert_eq(MazeProgress.locks(ids, done, false), [false, false, true, false] as Array[bool])
	assert_eq(MazeProgress.locks(ids, {}, true), [false, false, false, false] as Array[bool])


func test_unlock_all_setting_is_saved_and_read() -> void:
	var settings := GameSettings.new()
	settings.set_value("unlock_all_boards", true)
	settings.save_file(SETTINGS)
	var again := GameSettings.new()
	assert_eq(again.load_file(SETTINGS), "")
	assert_true(again.unlock_all_boards)
	again.reset_to_defaults()
	assert_false(again.unlock_all_boards)


func test_level_select_locks_and_medals() -> void:
	var cards: Array[LevelCard] = await _maze_cards()
	assert_false(cards[0].locked, "the first board is open")
	assert_true(cards[1].locked and cards[1].disabled, "the second waits for the first")
	assert_string_contains(cards[1].tooltip_text, cards[0].level.display_name)
	var gold: float = cards[0].level.medal_times_easy[0]
	_record(cards[0].level.board_id, gold - 0.5)
	cards = await _maze_cards()
	assert_false(cards[1].locked, "finishing the first opens the second")
	assert_true(cards[2].locked)
	assert_eq(_badges(cards[0]).easy_medal, Medals.Medal.GOLD)
	App.settings.unlock_all_boards = true
	for card in await _maze_cards():
		assert_false(card.locked, "Unlock all opens %s" % card.board_path)


func test_easy_and_hard_keep_their_own_medal_and_time() -> void:
	var cards: Array[LevelCard] = await _maze_cards()
	var first := cards[0]
	var hard_gold: float = first.level.medal_times_hard[0]
	var easy_bronze: float = first.level.medal_times_easy[2]
	App.record_maze_time(first.level.board_id, true, hard_gold - 0.1)
	App.record_maze_time(first.level.board_id, false, easy_bronze)
	cards = await _maze_cards()
	var badges := _badges(cards[0])
	assert_eq(badges.hard_medal, Medals.Medal.GOLD, "a hard finish earns the hard medal")
	assert_eq(badges.easy_medal, Medals.Medal.BRONZE, "the easy medal from the easy time")
	var text := " ".join(cards[0].texts())
	assert_string_contains(text, "Easy %s" % MazeWinSummary.clock(easy_bronze))
	assert_string_contains(text, " · Hard %s" % MazeWinSummary.clock(hard_gold - 0.1))
	assert_false(cards[1].locked, "a hard finish opens the next board too")
	var rows := badges.row_texts()
	var easy: PackedFloat64Array = first.level.medal_times_easy
	assert_eq(
		rows[0],
		(
			"Easy: Gold · gold %s, silver %s, bronze %s"
			% [
				MazeWinSummary.clock(easy[0]),
				MazeWinSummary.clock(easy[1]),
				MazeWinSummary.clock(easy[2])
			]
		),
		"the card shows the three easy times, and the better medal (hard plays the same here)"
	)
	# First Roll has no black holes: one row (a play trial read a Hard row of the same
	# times as clutter)
	assert_eq(rows.size(), 1, "no separate Hard row")


func _maze_cards() -> Array[LevelCard]:
	App.level_select_kind = "maze"
	var screen := LevelSelectScene.instantiate() as LevelSelect
	# a scratch My boards folder: the tests never see the player's own boards
	screen.user_root = EMPTY_USER_ROOT
	add_child_autofree(screen)
	await wait_until(func() -> bool: return not screen.is_loading(), 20.0)
	var out: Array[LevelCard] = []
	for card: Button in screen.cards():
		out.append(card as LevelCard)
	return out


func _badges(card: LevelCard) -> MedalBadges:
	for node in card.find_children("*", "Control", true, false):
		if node is MedalBadges:
			return node as MedalBadges
	return null


# Records an easy-mode finish.
func _record(board_id: String, seconds: float) -> void:
	App.record_maze_time(board_id, false, seconds)


func test_the_way_in_is_one_ball_then_two_then_four() -> void:
	var balls := PackedInt32Array()
	for board_id in MazeProgress.ORDER:
		var level := BoardLoader.load_board(MazeProgress.shipped_path(board_id)).level
		balls.append(level.ball_starts.size())
	assert_eq(balls[0], 1, "the first board has one ball")
	assert_eq(balls[1], 2, "the second two")
	for i in range(2, balls.size()):
		assert_eq(balls[i], 4, "then four: %s" % MazeProgress.ORDER[i])


# Two blind play trials found the third board a wall after the second (two balls, no holes,
# to four balls and three holes): the first four-ball board brings at most two holes, and
# the fewest of the four-ball boards.
func test_the_first_four_ball_board_is_a_gentle_step() -> void:
	var first := BoardLoader.load_board(MazeProgress.shipped_path(MazeProgress.ORDER[2])).level
	assert_lte(first.holes.size(), 2, "%s: at most two holes" % first.board_id)
	for i in range(3, MazeProgress.ORDER.size()):
		var later := BoardLoader.load_board(MazeProgress.shipped_path(MazeProgress.ORDER[i])).level
		assert_lte(first.holes.size(), later.holes.size(), "no more holes than %s" % later.board_id)


func test_the_autoplay_finishes_the_first_board_in_under_30_s() -> void:
	var first := BoardLoader.load_board(MazeProgress.shipped_path(MazeProgress.ORDER[0])).level
	var played := MazeAutoplay.run(first, 60.0, 1, false)
	assert_true(played["won"])
	assert_lt(float(played["time_to_win"]), 30.0)


# Trial 10: locked cards offered "Export…" (the button under the card and the card's menu).
func test_a_locked_board_offers_no_export() -> void:
	App.level_select_kind = "maze"
	var screen := LevelSelectScene.instantiate() as LevelSelect
	screen.user_root = EMPTY_USER_ROOT
	add_child_autofree(screen)
	await wait_until(func() -> bool: return not screen.is_loading(), 20.0)
	var cards := screen.cards()
	var open := cards[0] as LevelCard
	var locked := cards[1] as LevelCard
	assert_true(locked.locked, "the second board waits for the first")
	assert_true((open.get_parent() as LevelSlot).export_button().visible, "open: Export…")
	assert_false((locked.get_parent() as LevelSlot).export_button().visible, "locked: none")
	screen.open_card_menu(locked)
	assert_false(screen.card_menu().entries().has("Export a copy…"), "nor in its menu")
	screen.card_menu().hide()
	screen.open_card_menu(open)
	assert_true(screen.card_menu().entries().has("Export a copy…"), "the open one's menu has it")
	screen.card_menu().hide()


# Trial 5: Enter on a locked board did nothing. Now it knocks and says what opens it.
func test_enter_on_a_locked_board_says_what_opens_it() -> void:
	App.level_select_kind = "maze"
	var screen := LevelSelectScene.instantiate() as LevelSelect
	screen.user_root = EMPTY_USER_ROOT
	add_child_autofree(screen)
	await wait_until(func() -> bool: return not screen.is_loading(), 20.0)
	var cards := screen.cards()
	var locked := cards[1] as LevelCard
	assert_true(locked.locked, "the second board waits for the first")
	locked.grab_focus()
	var sounds := screen.get_node("UiSounds") as UiSounds
	var before := sounds.played_count()
	for pressed: bool in [true, false]:
		var event := InputEventAction.new()
		event.action = &"ui_accept"
		event.pressed = pressed
		Input.parse_input_event(event)
		await get_tree().process_frame
	var first := (cards[0] as LevelCard).level.display_name
	assert_eq(screen.status_text(), "Finish %s to unlock this board" % first)
	assert_eq(sounds.played_count(), before + 1, "a sound with it")
	assert_true(is_instance_valid(screen) and screen.is_inside_tree(), "no game started")
