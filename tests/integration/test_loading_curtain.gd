extends GutTest
## The first minute (issue 41): every screen change shows a sign of life at once, the
## loading curtain, until the new screen has drawn; the board load took seconds with none.

const PACHINKO := "res://scenes/pachinko/pachinko_game.tscn"
const LEVEL_SELECT := "res://scenes/menu/level_select.tscn"
const MAX_FRAMES := 600


func after_each() -> void:
	var scene := get_tree().current_scene
	if scene != null:
		get_tree().current_scene = null
		scene.queue_free()
	App.curtain.lift()
	await get_tree().process_frame


func test_choosing_a_board_raises_the_curtain_until_the_game_has_drawn() -> void:
	App.start_game("pachinko", "res://levels/pachinko/classic.board")
	assert_true(App.curtain.is_covering(), "up the moment the board is chosen")
	assert_eq(App.curtain.words(), "Loading…")
	var frames := 0
	while frames < MAX_FRAMES:
		var scene := get_tree().current_scene
		if scene != null and scene.scene_file_path == PACHINKO:
			break
		assert_true(App.curtain.is_covering(), "and up all the while the board loads")
		await get_tree().process_frame
		frames += 1
	assert_lt(frames, MAX_FRAMES, "the game opened")
	await wait_process_frames(4)
	assert_false(App.curtain.is_covering(), "down once the game is on the screen")


func test_the_curtain_is_over_every_screen_and_takes_the_clicks_made_meanwhile() -> void:
	var curtain := App.curtain
	assert_gt(curtain.layer, 20, "over the pause menu and the frame counter")
	curtain.cover()
	var shade := curtain.get_child(0) as Control
	assert_eq(shade.mouse_filter, Control.MOUSE_FILTER_STOP)
	assert_eq(shade.get_anchor(SIDE_RIGHT), 1.0, "across the whole window")
	assert_eq(shade.get_anchor(SIDE_BOTTOM), 1.0)
	curtain.lift()
	assert_false(curtain.is_covering())


func test_a_second_change_keeps_the_curtain_up_for_its_own_screen() -> void:
	App.go_to_level_select("pachinko")
	App.start_game("pachinko", "res://levels/pachinko/classic.board")
	for frame in 3:
		await get_tree().process_frame
	var scene := get_tree().current_scene
	if scene == null or scene.scene_file_path != PACHINKO:
		assert_true(App.curtain.is_covering(), "the level select's arrival does not lower it")
	for frame in MAX_FRAMES:
		scene = get_tree().current_scene
		if scene != null and scene.scene_file_path == PACHINKO:
			break
		await get_tree().process_frame
	await wait_process_frames(4)
	assert_false(App.curtain.is_covering())


func test_the_game_loads_while_the_player_picks_a_board() -> void:
	App.go_to_level_select("pachinko")
	for frame in MAX_FRAMES:
		var scene := get_tree().current_scene
		if scene != null and scene.scene_file_path == LEVEL_SELECT and not App.curtain.visible:
			break
		await get_tree().process_frame
	await wait_process_frames(2)
	var status := ResourceLoader.load_threaded_get_status(PACHINKO)
	assert_ne(status, ResourceLoader.THREAD_LOAD_INVALID_RESOURCE, "the game's scene is loading")
	App.start_game("pachinko", "res://levels/pachinko/classic.board")
	for frame in MAX_FRAMES:
		var scene := get_tree().current_scene
		if scene != null and scene.scene_file_path == PACHINKO:
			break
		await get_tree().process_frame
	assert_eq(get_tree().current_scene.scene_file_path, PACHINKO, "and opens from it")
