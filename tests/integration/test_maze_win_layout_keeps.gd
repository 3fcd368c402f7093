extends GutTest
## The maze screen keeps its layout between attempts of the same board in the same window: a
## play trial saw the board frame move and resize a few px, the side column narrow, "Tilt the
## board to start!" wrap onto two lines and the joystick shrink from ~73 to ~55 px after
## Space, Retry and H, as the panel was laid out again for the texts of the moment.

const GAME := preload("res://scenes/maze/maze_game.tscn")
const StretchedWindow := preload("res://tests/integration/stretched_window.gd")
const TEST_SETTINGS := "user://test_maze_win_layout_settings.cfg"
const TEST_SAVE := "user://test_maze_win_layout_save.cfg"
const REPLAYS := "user://test_maze_win_layout_replays"

var _kept_save: SaveData


func before_all() -> void:
	App.load_player_files(TEST_SETTINGS, TEST_SAVE)
	ReplayStore.folder = REPLAYS


func after_all() -> void:
	App.maze_hard_chosen = false  # H here is the player's choice for the next board
	App.load_player_files(App.SETTINGS_PATH, App.SAVE_PATH)
	ReplayStore.folder = ReplayStore.DIR
	for file_name in DirAccess.get_files_at(REPLAYS):
		DirAccess.remove_absolute(ProjectSettings.globalize_path(REPLAYS + "/" + file_name))
	DirAccess.remove_absolute(ProjectSettings.globalize_path(REPLAYS))
	for path in [TEST_SETTINGS, TEST_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


func before_each() -> void:
	App.maze_hard_chosen = false  # H here is the player's choice for the next board
	_kept_save = App.save_data
	App.save_data = SaveData.new()  # in memory only: never written


func after_each() -> void:
	App.save_data = _kept_save


# What the player sees of the layout: the board's region, the side column, the joystick and
# the start note's headline height.
func _layout_of(game: MazeGame) -> Dictionary:
	var side: Control = game.get_node("Side")
	var headline: Label = game.get_node("%Note").get_node("Headline")
	return {
		"region": game.lay_out(),
		"side": side.get_global_rect(),
		"joystick": game.get_node("%Joystick").get_rect(),
		"headline lines": headline.get_line_count(),
	}


func _win(game: MazeGame) -> void:
	var rules := game.rules
	game._start()
	for i in 20:
		rules.step()
	var ids := rules.world.get_ids()
	for i in ids.size():
		rules.world.set_ball_position(ids[i], rules.level.goal_center + Vector2(i * 10 - 15, 0))
	rules.step()


func _assert_same(first: Dictionary, now: Dictionary, after: String) -> void:
	for key: String in first.keys():
		assert_eq(now[key], first[key], "%s: the same %s" % [after, key])


func test_the_layout_is_the_same_on_every_attempt(
	size: Vector2i = use_parameters([Vector2i(900, 700), Vector2i(1280, 720), Vector2i(720, 1280)])
) -> void:
	var game: MazeGame = await StretchedWindow.open(self, GAME, size, 12)
	var first := _layout_of(game)
	_win(game)
	await wait_process_frames(4)
	game.win_panel().buttons()[1].pressed.emit()  # Retry
	await wait_process_frames(8)
	_assert_same(first, _layout_of(game), "after a win and Retry")
	_win(game)
	await wait_process_frames(4)
	var hard := InputEventAction.new()
	hard.action = &"maze_hard_mode"
	hard.pressed = true
	game._unhandled_input(hard)
	await wait_process_frames(8)
	var reset := InputEventAction.new()
	reset.action = &"maze_easy_mode"
	reset.pressed = true
	game._unhandled_input(reset)
	await wait_process_frames(8)
	_assert_same(first, _layout_of(game), "after H, E")


# The help line breaks only between its items, and no line starts or ends with a separator:
# trial 6 saw "E easy ·" end a line (the dot kept with the item before it); an earlier trial a
# line start "· Escape pause". The items are set apart by plain spaces, which a wrapped line
# drops at its ends, and nothing else.
func test_the_help_line_breaks_only_between_its_items() -> void:
	var keys := MazeHints.controls().split("\n")[1]
	assert_false(keys.contains("·"), "no separator mark to dangle: %s" % keys)
	var items := keys.split(MazeHints.ITEM_GAP)
	assert_eq(items.size(), 5, "fine tilt, reset, hard, easy and pause")
	for item in items:
		assert_false(item.contains(" "), "'%s' holds together" % item)
		assert_ne(item.strip_edges(), "", "no empty item")
