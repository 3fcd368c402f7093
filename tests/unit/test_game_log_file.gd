extends GutTest
## The game's own log file: what the engine's wrote, in its format, without the release
## build's false disconnect report (4,286 of them in one trial's log), and rotated as the
## engine rotated its own.

const FALSE_CODE := "!s->slot_map.has(*p_callable.get_base_comparator())"
const FALSE_MESSAGE := (
	"Attempt to disconnect a nonexistent connection from 'Notice:<PanelContainer#11431>'."
	+ " Signal: '%s', callable: ''."
)

var _folder := ""


func before_each() -> void:
	_folder = "user://test_game_log_%d" % Time.get_ticks_usec()
	DirAccess.make_dir_recursive_absolute(_folder)


func after_each() -> void:
	for name in DirAccess.get_files_at(_folder):
		DirAccess.remove_absolute(_folder.path_join(name))
	DirAccess.remove_absolute(_folder)


func _log_at() -> String:
	return _folder.path_join("godot.log")


func _report(log: GameLogFile, function: String, file: String, code: String, said: String) -> void:
	log._log_error(function, file, 1764, code, said, false, 0, [] as Array[ScriptBacktrace])


func _text() -> String:
	return FileAccess.get_file_as_string(_log_at())


func test_prints_and_real_errors_are_written_in_the_engines_format() -> void:
	var log := GameLogFile.new(_log_at())
	assert_true(log.is_open())
	log._log_message("Board Studio 0.1.0\n", false)
	_report(log, "load_board", "res://scripts/board/board_file.gd", "", "The board file is broken.")
	var text := _text()
	assert_true(text.begins_with("Board Studio "), "the log opens with what is running: " + text)
	assert_string_contains(text, " on Godot 4.6")
	assert_string_contains(text, "Board Studio 0.1.0\n")
	assert_string_contains(
		text,
		"ERROR: The board file is broken.\n   at: load_board (res://scripts/board/board_file.gd:1764)\n"
	)


func test_the_false_disconnect_report_is_left_out() -> void:
	var log := GameLogFile.new(_log_at())
	for signal_name in ["size_flags_changed", "visibility_changed"]:
		_report(
			log, "_disconnect", "core/object/object.cpp", FALSE_CODE, FALSE_MESSAGE % signal_name
		)
	# the condition alone (a build that carries no message) is the same report
	_report(log, "_disconnect", "core/object/object.cpp", FALSE_CODE, "")
	assert_eq(log.left_out, 3)
	assert_false(_text().contains("ERROR"), "no ERROR line in the log: " + _text())


func test_a_real_disconnect_mistake_is_still_written() -> void:
	var log := GameLogFile.new(_log_at())
	# our own callables always have a name, and other signals are not the container's
	var named := FALSE_MESSAGE.replace("callable: ''", "callable: 'MainMenu::_on_play'")
	_report(log, "_disconnect", "core/object/object.cpp", FALSE_CODE, named % "pressed")
	_report(log, "_disconnect", "core/object/object.cpp", FALSE_CODE, FALSE_MESSAGE % "pressed")
	assert_eq(log.left_out, 0)
	assert_eq(_text().count("ERROR: Attempt to disconnect"), 2)


func test_the_last_log_is_kept_and_only_the_newest_five_stay() -> void:
	for run in 7:
		var log := GameLogFile.new(_log_at())
		log._log_message("run %d\n" % run, false)
		log = null  # closes the file
		# each run's log gets its own time in its kept name
		var stamp := "2026-11-2%dT10.00.00" % run
		var kept := _folder.path_join("godot%s.log" % stamp)
		DirAccess.rename_absolute(_log_at(), kept)
		var last_run := FileAccess.open(_log_at(), FileAccess.WRITE)
		last_run.store_string("run %d\n" % run)
		last_run.close()
	var last := GameLogFile.new(_log_at())
	assert_true(last.is_open())
	var names := DirAccess.get_files_at(_folder)
	assert_eq(names.size(), GameLogFile.MAX_FILES, "logs kept: %s" % [names])
	assert_true(names.has("godot.log"))
	var older := Array(names).filter(func(name: String) -> bool: return name != "godot.log")
	var previous := ""
	for name: String in older:
		if FileAccess.get_file_as_string(_folder.path_join(name)) == "run 6\n":
			previous = name
	assert_ne(previous, "", "the last run's log is kept under its time: %s" % [names])
	assert_false(names.has("godot2026-11-20T10.00.00.log"), "the oldest is removed")
	assert_eq(
		FileAccess.get_file_as_string(_log_at()),
		GameLogFile.heading(),
		"the new log holds its heading"
	)


func test_the_game_writes_its_own_log_and_the_engines_is_off() -> void:
	# The engine's file log would hold the false reports; ours is on in the running game.
	assert_false(
		ProjectSettings.get_setting("debug/file_logging/enable_file_logging.pc", true),
		"project.godot turns the engine's file log off on desktops"
	)
	assert_true(FileAccess.file_exists(GameLogFile.LOG_PATH), "the App autoload opened the log")
