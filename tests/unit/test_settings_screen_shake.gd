extends GutTest
## The screen shake setting: on by default, kept across a save and a load, a bad value in
## the file named and replaced by the default, and the settings screen has its toggle.

const PATH := "user://test_settings_screen_shake.cfg"
const SETTINGS_SCREEN := "res://scenes/menu/settings_menu.tscn"


func after_each() -> void:
	DirAccess.remove_absolute(PATH)


func test_on_by_default_and_kept_across_a_save() -> void:
	var saved := GameSettings.new()
	assert_true(saved.screen_shake, "on by default")
	saved.set_value("screen_shake", false)
	assert_eq(saved.save_file(PATH), OK)
	assert_string_contains(FileAccess.get_file_as_string(PATH), "screen_shake=false")
	var loaded := GameSettings.new()
	assert_eq(loaded.load_file(PATH), "")
	assert_false(loaded.screen_shake, "off after a load")


func test_a_bad_value_is_named_and_the_default_used() -> void:
	var file := FileAccess.open(PATH, FileAccess.WRITE)
	file.store_string('[meta]\nversion=1\n\n[display]\nscreen_shake="wobbly"\n')
	file.close()
	var loaded := GameSettings.new()
	assert_string_contains(loaded.load_file(PATH), "screen_shake")
	assert_true(loaded.screen_shake)


func test_the_settings_screen_toggles_it() -> void:
	var before := App.settings.screen_shake
	var screen := (load(SETTINGS_SCREEN) as PackedScene).instantiate()
	add_child_autofree(screen)
	var toggle := screen.get_node("%ScreenShakeCheck") as Button
	assert_eq(toggle.button_pressed, before)
	toggle.button_pressed = not before
	assert_eq(App.settings.screen_shake, not before, "the toggle changes the setting")
	assert_eq(toggle.text, "On" if not before else "Off")
	App.settings.set_value("screen_shake", before)
