extends GutTest
## Player settings: a save/load round trip, readable text, and recovery from damaged,
## newer-version and out-of-range files (defaults, one clear message, never a crash).

const PATH := "user://test_settings.cfg"


func after_each() -> void:
	for name in DirAccess.get_files_at("user://"):
		if name.begins_with(PATH.get_file()):
			DirAccess.remove_absolute("user://" + name)


func _write(text: String) -> void:
	var file := FileAccess.open(PATH, FileAccess.WRITE)
	file.store_string(text)
	file.close()


func test_values_survive_a_round_trip() -> void:
	var saved := GameSettings.new()
	saved.set_value("master_volume", 0.35)
	saved.set_value("sfx_volume", 0.8)
	saved.set_value("fullscreen", true)
	saved.set_value("show_frame_counter", true)
	saved.set_value("tilt_sensitivity", 1.75)
	assert_eq(saved.save_file(PATH), OK)
	var loaded := GameSettings.new()
	assert_eq(loaded.load_file(PATH), "")
	assert_almost_eq(loaded.master_volume, 0.35, 0.0001)
	assert_almost_eq(loaded.sfx_volume, 0.8, 0.0001)
	assert_true(loaded.fullscreen)
	assert_true(loaded.show_frame_counter)
	assert_almost_eq(loaded.tilt_sensitivity, 1.75, 0.0001)


func test_file_is_readable_text() -> void:
	var settings := GameSettings.new()
	settings.save_file(PATH)
	var text := FileAccess.get_file_as_string(PATH)
	assert_string_contains(text, "[meta]\nversion=%d" % GameSettings.VERSION)
	assert_string_contains(text, "master_volume=")
	assert_string_contains(text, 'tilt_left=["key:Left"')


func test_missing_file_gives_defaults_without_a_message() -> void:
	var settings := GameSettings.new()
	settings.set_value("master_volume", 0.1)
	assert_eq(settings.load_file("user://no_such_settings.cfg"), "")
	assert_eq(settings.master_volume, 1.0)


func test_damaged_file_is_reported_and_defaults_used() -> void:
	_write("[audio\nmaster_volume = ]]{{ not a value\n")
	var settings := GameSettings.new()
	settings.set_value("tilt_sensitivity", 2.0)
	var message := settings.load_file(PATH)
	assert_string_contains(message, PATH.get_file())
	assert_string_contains(message, "could not be read")
	assert_eq(settings.tilt_sensitivity, 1.0)
	assert_eq(settings.master_volume, 1.0)


func test_binary_garbage_is_reported() -> void:
	var file := FileAccess.open(PATH, FileAccess.WRITE)
	file.store_buffer(PackedByteArray([0, 159, 146, 150, 0, 255, 10, 91]))
	file.close()
	var message := GameSettings.new().load_file(PATH)
	assert_string_contains(message, "NUL bytes")


func test_newer_version_is_reported_defaults_used_and_never_saved_over() -> void:
	var newer := "[meta]\nversion=99\n\n[audio]\nmaster_volume=0.2\n"
	_write(newer)
	var settings := GameSettings.new()
	var message := settings.load_file(PATH)
	assert_string_contains(message, "newer version")
	assert_string_contains(message, "99")
	assert_string_contains(message, "left as it is")
	assert_eq(settings.master_volume, 1.0)
	settings.set_value("master_volume", 0.7)
	assert_eq(settings.save_file(PATH), ERR_FILE_NO_PERMISSION)
	assert_eq(FileAccess.get_file_as_string(PATH), newer, "the newer file is untouched")
	assert_eq(settings.save_file(PATH + ".other"), OK, "other paths still save")


func test_missing_version_is_reported_as_damage() -> void:
	_write("[audio]\nmaster_volume=0.2\n")
	assert_string_contains(GameSettings.new().load_file(PATH), "no [meta] version")


func test_bad_values_are_named_and_the_rest_kept() -> void:
	_write(
		(
			"[meta]\nversion=1\n[audio]\nmaster_volume=7\nsfx_volume=0.5\n"
			+ '[display]\nfullscreen="yes"\n[input]\npause=["key:NoSuchKey"]\n'
		)
	)
	var settings := GameSettings.new()
	var message := settings.load_file(PATH)
	assert_string_contains(message, "master_volume")
	assert_string_contains(message, "fullscreen")
	assert_string_contains(message, "pause")
	assert_eq(settings.master_volume, 1.0, "out of range is clamped")
	assert_almost_eq(settings.sfx_volume, 0.5, 0.0001, "good values are kept")
	assert_false(settings.fullscreen)
	assert_eq(settings.events_for("pause").size(), GameSettings.default_bindings()["pause"].size())


func test_set_value_clamps_tilt_sensitivity() -> void:
	var settings := GameSettings.new()
	settings.set_value("tilt_sensitivity", 100.0)
	assert_eq(settings.tilt_sensitivity, GameSettings.MAX_TILT_SENSITIVITY)
	settings.set_value("tilt_sensitivity", -1.0)
	assert_eq(settings.tilt_sensitivity, GameSettings.MIN_TILT_SENSITIVITY)


func test_every_project_action_is_remappable_and_ui_actions_are_not() -> void:
	var actions := GameSettings.remappable_actions()
	for action: String in ["launch_charge", "tilt_left", "pause", "toggle_frame_counter"]:
		assert_has(actions, action)
	for action in actions:
		assert_false(action.begins_with("ui_"), action)
