extends GutTest
## A right click on a level select card focuses it and opens its own menu (Play, Export a
## copy…, and Delete… on the player's boards), as the board_actions key does.

const LevelSelectScene := preload("res://scenes/menu/level_select.tscn")
const ROOT := "user://test_level_select_right_click"
const CLASSIC := "res://levels/pachinko/classic.board"


func before_each() -> void:
	DirAccess.make_dir_recursive_absolute(ROOT + "/pachinko")
	var file := FileAccess.open(ROOT + "/pachinko/mine.board", FileAccess.WRITE)
	file.store_string(FileAccess.get_file_as_string(CLASSIC))
	file.close()


func after_all() -> void:
	DirAccess.remove_absolute(ProjectSettings.globalize_path(ROOT + "/pachinko/mine.board"))
	DirAccess.remove_absolute(ProjectSettings.globalize_path(ROOT + "/pachinko"))
	DirAccess.remove_absolute(ProjectSettings.globalize_path(ROOT))


func _open() -> LevelSelect:
	App.level_select_kind = "pachinko"
	var screen := LevelSelectScene.instantiate() as LevelSelect
	screen.user_root = ROOT
	add_child_autofree(screen)
	await wait_until(func() -> bool: return not screen.is_loading(), 20.0)
	await wait_process_frames(3)
	return screen


# The card gets the click as the GUI hands it one (gui_input; the GUI's own picking of the
# control under the mouse is Godot's, and a left click would start a game).
func _right_click(card: Control) -> void:
	for pressed: bool in [true, false]:
		var click := InputEventMouseButton.new()
		click.button_index = MOUSE_BUTTON_RIGHT
		click.pressed = pressed
		click.position = card.size * 0.5
		card.gui_input.emit(click)
		await wait_process_frames(1)


func test_a_right_click_opens_the_cards_menu() -> void:
	var screen: LevelSelect = await _open()
	var menu: PopupMenu = screen.card_menu()
	var my_card: Control = (screen.my_slots() as Array)[0].get("card")
	assert_false(menu.visible)
	await _right_click(my_card)
	assert_true(menu.visible, "a right click opens the card's menu")
	assert_true(my_card.has_focus(), "and the card has the focus")
	assert_eq(menu.entries(), PackedStringArray(["Play", "Export a copy…", "Delete…"]))
	menu.hide()
