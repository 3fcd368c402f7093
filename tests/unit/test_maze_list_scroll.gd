extends GutTest
## The maze's board list opens where the player is: at the top while it loads, then on the
## card of the board last played (trial 5 saw it open scrolled down while loading), and
## without the title screen's falling balls behind its cards.

const LevelSelectScene := preload("res://scenes/menu/level_select.tscn")
const StretchedWindow := preload("res://tests/integration/stretched_window.gd")
const ScratchSave := preload("res://tests/helpers/scratch_save.gd")
const SAVE := "user://test_maze_list_scroll_save.cfg"
const EMPTY_USER_ROOT := "user://test_maze_list_scroll_no_boards"

var _real_save: RefCounted = null
var _unlock_all := false


func before_each() -> void:
	_real_save = ScratchSave.swap_in(SAVE)
	_unlock_all = App.settings.unlock_all_boards
	App.settings.unlock_all_boards = true


func after_each() -> void:
	App.settings.unlock_all_boards = _unlock_all
	ScratchSave.restore(_real_save, SAVE)


func after_all() -> void:
	App.request_board(BoardLevel.MAZE_NAME, "res://levels/maze/classic.board")


# Opens the maze list and returns [screen, the scroll's offsets frame by frame].
func _open() -> Array:
	App.level_select_kind = BoardLevel.MAZE_NAME
	var window := StretchedWindow.make(Vector2i(1280, 720))
	add_child_autofree(window)
	var screen := LevelSelectScene.instantiate() as LevelSelect
	screen.user_root = EMPTY_USER_ROOT
	window.add_child(screen)
	var scroll := screen.get_node("%Scroll") as ScrollContainer
	var seen: Array[int] = []
	for i in 600:
		await get_tree().process_frame
		seen.append(scroll.scroll_vertical)
		if not screen.is_loading() and i > 30:
			break
	for i in 5:
		await get_tree().process_frame
		seen.append(scroll.scroll_vertical)
	return [screen, seen]


func test_the_list_opens_at_its_top_when_the_first_board_is_chosen() -> void:
	App.request_board(BoardLevel.MAZE_NAME, "res://levels/maze/first_roll.board")
	var opened: Array = await _open()
	var seen: Array[int] = opened[1]
	assert_eq(seen.max(), 0, "never scrolled down while loading: %s" % [seen])


func test_the_list_opens_on_the_board_last_played() -> void:
	App.request_board(BoardLevel.MAZE_NAME, "res://levels/maze/the_deep.board")
	var opened: Array = await _open()
	var screen: LevelSelect = opened[0]
	var scroll := screen.get_node("%Scroll") as ScrollContainer
	var focused := screen.get_viewport().gui_get_focus_owner() as LevelCard
	assert_not_null(focused)
	assert_eq(focused.board_path, "res://levels/maze/the_deep.board", "its card has the focus")
	var card := focused.get_global_rect()
	var view := scroll.get_global_rect()
	assert_true(view.encloses(card), "and is in view: card %s, list %s" % [card, view])


# Trial 5 saw the title's falling balls roll over the board list; the list keeps them off.
func test_the_falling_balls_stay_on_the_title_screen() -> void:
	var opened: Array = await _open()
	var screen: LevelSelect = opened[0]
	var backdrop := screen.get_node("BackdropLayer/Backdrop") as MenuBackdrop
	assert_false(backdrop.falling_balls, "no balls behind the cards")
	var menu: Node = (load("res://scenes/menu/main_menu.tscn") as PackedScene).instantiate()
	add_child_autofree(menu)
	var title_backdrop := menu.get_node("BackdropLayer/Backdrop") as MenuBackdrop
	assert_true(title_backdrop.falling_balls, "the title screen keeps them")
