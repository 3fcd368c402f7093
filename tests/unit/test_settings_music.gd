extends GutTest
## The music volume setting (issue 41): 60 % by default, kept across a save and a load,
## pushed onto the Music bus, a bad value in the file named in the problem sentence and
## replaced by the default (or clamped into 0..1), and the settings screen has its slider.

const PATH := "user://test_settings_music.cfg"
const SETTINGS_SCREEN := "res://scenes/menu/settings_menu.tscn"


func after_each() -> void:
	DirAccess.remove_absolute(PATH)
	App.settings.apply()


func _write(text: String) -> void:
	var file := FileAccess.open(PATH, FileAccess.WRITE)
	file.store_string(text)
	file.close()


func test_kept_across_a_save_and_a_load() -> void:
	var saved := GameSettings.new()
	assert_almost_eq(saved.music_volume, GameSettings.DEFAULT_MUSIC_VOLUME, 0.0001, "default")
	saved.set_value("music_volume", 0.25)
	assert_eq(saved.save_file(PATH), OK)
	assert_string_contains(FileAccess.get_file_as_string(PATH), "music_volume=0.25")
	var loaded := GameSettings.new()
	assert_eq(loaded.load_file(PATH), "")
	assert_almost_eq(loaded.music_volume, 0.25, 0.0001)


func test_the_music_bus_follows_it() -> void:
	var bus := AudioServer.get_bus_index(&"Music")
	assert_gte(bus, 0, "the project has a Music bus")
	assert_eq(AudioServer.get_bus_send(bus), &"Master", "under the master volume")
	var settings := GameSettings.new()
	settings.set_value("music_volume", 0.5)
	settings.apply()
	assert_almost_eq(AudioServer.get_bus_volume_db(bus), linear_to_db(0.5), 0.01)
	assert_false(AudioServer.is_bus_mute(bus))
	settings.set_value("music_volume", 0.0)
	settings.apply()
	assert_true(AudioServer.is_bus_mute(bus), "0 is silence")


func test_a_value_that_is_not_a_number_is_named_and_the_default_used() -> void:
	_write('[meta]\nversion=1\n\n[audio]\nmusic_volume="loud"\nsfx_volume=0.4\n')
	var loaded := GameSettings.new()
	var message := loaded.load_file(PATH)
	assert_string_contains(message, "music_volume")
	assert_string_contains(message, "could not be used")
	assert_almost_eq(loaded.music_volume, GameSettings.DEFAULT_MUSIC_VOLUME, 0.0001)
	assert_almost_eq(loaded.sfx_volume, 0.4, 0.0001, "the good values are kept")


func test_a_value_out_of_range_is_named_and_clamped() -> void:
	_write("[meta]\nversion=1\n\n[audio]\nmusic_volume=3.5\n")
	var loaded := GameSettings.new()
	assert_string_contains(loaded.load_file(PATH), "music_volume")
	assert_eq(loaded.music_volume, 1.0)
	_write("[meta]\nversion=1\n\n[audio]\nmusic_volume=-2\n")
	assert_string_contains(loaded.load_file(PATH), "music_volume")
	assert_eq(loaded.music_volume, 0.0)
	loaded.set_value("music_volume", 9.0)
	assert_eq(loaded.music_volume, 1.0, "the screen's setter clamps too")


func test_the_settings_screen_has_its_slider() -> void:
	var before := App.settings.music_volume
	var screen := (load(SETTINGS_SCREEN) as PackedScene).instantiate()
	add_child_autofree(screen)
	var slider := screen.get_node("%MusicSlider") as HSlider
	assert_almost_eq(slider.value, before, 0.0001)
	slider.value = 0.3
	assert_almost_eq(App.settings.music_volume, 0.3, 0.0001, "the slider changes the setting")
	assert_eq((screen.get_node("%MusicValue") as Label).text, "30%")
	App.settings.set_value("music_volume", before)
