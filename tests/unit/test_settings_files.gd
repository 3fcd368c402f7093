extends GutTest
## What happens to settings.cfg and save.cfg on disk: a damaged file is moved aside before a
## new one is written and the player's message names where it went; a newer version's file
## is never written during the run; BOM and CRLF files read as usual; pause always keeps a
## binding, from the file and from the settings screen.

const AppScript := preload("res://scenes/app/app.gd")
const SETTINGS := "user://test_settings_files_settings.cfg"
const SAVE := "user://test_settings_files_save.cfg"


func after_each() -> void:
	for name in DirAccess.get_files_at("user://"):
		if name.begins_with("test_settings_files_"):
			DirAccess.remove_absolute("user://" + name)
	GameSettings.new().apply()


func _write(path: String, text: String) -> void:
	var file := FileAccess.open(path, FileAccess.WRITE)
	file.store_string(text)
	file.close()


func _kept_copies(path: String) -> PackedStringArray:
	var kept := PackedStringArray()
	for name in DirAccess.get_files_at("user://"):
		if name.begins_with(path.get_file() + ".bad-"):
			kept.append("user://" + name)
	return kept


func _load_in_app(settings_text: String, save_text: String) -> Array:
	_write(SETTINGS, settings_text)
	_write(SAVE, save_text)
	var app := AppScript.new()
	app.load_player_files(SETTINGS, SAVE)
	var problems: PackedStringArray = app.take_problems()
	return [app, problems]


func test_app_keeps_damaged_files_and_names_the_kept_copies() -> void:
	var loaded := _load_in_app("version 1, honest\n", "[meta]\nversion=nan\n")
	var app: AppScript = loaded[0]
	var problems: PackedStringArray = loaded[1]
	assert_eq(problems.size(), 2, "one message per file")
	for pair: Array in [[SETTINGS, problems[0]], [SAVE, problems[1]]]:
		var kept := _kept_copies(pair[0])
		assert_eq(kept.size(), 1, "%s kept once" % pair[0])
		var kept_name := ProjectSettings.globalize_path(kept[0])
		assert_string_contains(
			pair[1], kept_name, "the message names the kept file by its real path"
		)
		assert_true(kept_name.get_file().match("*.cfg.bad-????????-??????"), kept_name)
	assert_eq(FileAccess.get_file_as_string(_kept_copies(SETTINGS)[0]), "version 1, honest\n")
	assert_string_contains(FileAccess.get_file_as_string(SETTINGS), "[meta]", "defaults written")
	app.free()
	var again := AppScript.new()
	again.load_player_files(SETTINGS, SAVE)
	assert_eq((again.take_problems() as PackedStringArray).size(), 0, "reported once")
	again.free()


func test_a_second_damage_in_the_same_second_gets_its_own_copy() -> void:
	var when := {"year": 2030, "month": 1, "day": 2, "hour": 3, "minute": 4, "second": 5}
	_write(SETTINGS, "one")
	assert_eq(UserFile.keep_aside(SETTINGS, when), SETTINGS + ".bad-20300102-030405")
	_write(SETTINGS, "two")
	assert_eq(UserFile.keep_aside(SETTINGS, when), SETTINGS + ".bad-20300102-030405-2")
	assert_eq(FileAccess.get_file_as_string(SETTINGS + ".bad-20300102-030405"), "one")


func test_newer_files_are_never_written_during_the_run() -> void:
	var settings_text := "[meta]\nversion=3\n[audio]\nmaster_volume=0.1\n"
	var save_text := "[meta]\nversion=9\n[maze_best_seconds_easy]\nclassic=12.0\n"
	var loaded := _load_in_app(settings_text, save_text)
	var app: AppScript = loaded[0]
	var problems: PackedStringArray = loaded[1]
	assert_eq(problems.size(), 2)
	assert_string_contains(problems[0], "newer version")
	assert_string_contains(problems[1], "newer version")
	app.save_settings()
	assert_true(app.record_maze_time("classic", false, 5.0), "a best of this run counts")
	assert_eq(FileAccess.get_file_as_string(SETTINGS), settings_text, "settings untouched")
	assert_eq(FileAccess.get_file_as_string(SAVE), save_text, "best results untouched")
	assert_eq(_kept_copies(SETTINGS).size() + _kept_copies(SAVE).size(), 0, "nothing moved")
	app.free()


func test_bom_and_crlf_files_read_as_usual() -> void:
	_write(SETTINGS, "\ufeff[meta]\r\nversion=1\r\n[audio]\r\nmaster_volume=0.25\r\n")
	_write(SAVE, '\ufeff[meta]\r\nversion=2\r\n[maze_best_seconds_hard]\r\n"a=b"=9.5\r\n')
	var settings := GameSettings.new()
	assert_eq(settings.load_file(SETTINGS), "")
	assert_eq(settings.master_volume, 0.25)
	var data := SaveData.new()
	assert_eq(data.load_file(SAVE), "")
	assert_eq(data.best_maze_time("a=b", true), 9.5)


func test_wrong_types_are_refused_one_by_one() -> void:
	_write(
		SETTINGS,
		(
			'[meta]\nversion=1\n[audio]\nmaster_volume="0.5"\nsfx_volume=0.3\n'
			+ '[display]\nfullscreen={"on": true}\nshow_frame_counter=true\n'
			+ '[controls]\ntilt_sensitivity=[2]\n[input]\ngame_restart=["key:T"]\n'
			+ "[future]\nsomething=1\n[audio]\nan_unknown_key=5\n"
		)
	)
	var settings := GameSettings.new()
	var message := settings.load_file(SETTINGS)
	for key in ["master_volume", "fullscreen", "tilt_sensitivity"]:
		assert_string_contains(message, key)
	assert_false(message.contains("an_unknown_key"), "unknown keys are ignored")
	assert_false(message.contains("something"), "unknown sections are ignored")
	assert_eq(settings.master_volume, 1.0)
	assert_almost_eq(settings.sfx_volume, 0.3, 0.0001)
	assert_true(settings.show_frame_counter)
	assert_eq(settings.tilt_sensitivity, 1.0)
	assert_eq(settings.events_for("game_restart").size(), 1)


func test_an_empty_pause_list_keeps_the_default() -> void:
	_write(SETTINGS, "[meta]\nversion=1\n[input]\npause=[]\ngame_restart=[]\n")
	var settings := GameSettings.new()
	var message := settings.load_file(SETTINGS)
	assert_string_contains(message, "pause (it needs a binding)")
	var shipped: Array = GameSettings.default_bindings()["pause"]
	assert_eq(settings.events_for("pause").size(), shipped.size())
	assert_eq(settings.events_for("game_restart").size(), 0, "other actions may be left unbound")


func test_clearing_a_pause_column_restores_its_default() -> void:
	var settings := GameSettings.new()
	var shipped: Array = GameSettings.default_bindings()["pause"]
	var key := InputEventKey.new()
	key.physical_keycode = KEY_P
	settings.rebind("pause", key, false)
	assert_false(settings.clear_binding("pause", false), "the keyboard column comes back")
	assert_false(settings.clear_binding("pause", true), "so does the gamepad column")
	var codes := settings.events_for("pause").map(InputEventCodec.encode)
	assert_eq(codes, shipped.map(InputEventCodec.encode), "both columns are the shipped ones again")
	assert_true(settings.clear_binding("game_restart", false))
	assert_true(settings.clear_binding("game_restart", true))
	assert_eq(settings.events_for("game_restart").size(), 0, "other actions may be unbound")


func test_a_pause_list_without_a_gamepad_binding_gets_the_default_one() -> void:
	_write(SETTINGS, '[meta]\nversion=1\n[input]\npause=["key:P"]\n')
	var settings := GameSettings.new()
	assert_eq(settings.load_file(SETTINGS), "", "filled in quietly")
	var codes := settings.events_for("pause").map(InputEventCodec.encode)
	assert_has(codes, "key:P")
	assert_true(
		settings.events_for("pause").any(InputEventCodec.is_gamepad), "a gamepad pause is back"
	)


# Issue 39: on the release build every second start called both files damaged and moved
# them aside ("line 1 (outside a [section])"): the compressed scripts read the "\ufeff"
# literal as "", so the first character of every file was cut off. A file the game itself
# wrote must load with no problem, launch after launch, and stay where it is.
func test_files_the_game_wrote_load_cleanly_on_every_later_start() -> void:
	for start in 3:
		var app := AppScript.new()
		app.load_player_files(SETTINGS, SAVE)
		var problems: PackedStringArray = app.take_problems()
		assert_eq(problems, PackedStringArray(), "start %d: no file called damaged" % start)
		app.save_settings()
		app.save_data.save()
		app.free()
	assert_eq(_kept_copies(SETTINGS), PackedStringArray(), "settings.cfg never moved aside")
	assert_eq(_kept_copies(SAVE), PackedStringArray(), "save.cfg never moved aside")
	assert_true(FileAccess.get_file_as_string(SETTINGS).begins_with("; "), "header kept whole")


func test_only_a_leading_byte_order_mark_is_dropped() -> void:
	var text := "; comment\n[meta]\nversion=1\n"
	assert_eq(UserFile.decode(text.to_utf8_buffer()), {"text": text}, "no mark: text as it is")
	var marked := PackedByteArray([0xEF, 0xBB, 0xBF])
	marked.append_array(text.to_utf8_buffer())
	assert_eq(UserFile.decode(marked), {"text": text}, "the mark alone is dropped")
	assert_eq(UserFile.decode(PackedByteArray()), {"text": ""}, "an empty file is empty text")
