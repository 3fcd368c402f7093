class_name GameLogFile
extends Logger
## The game's log file, user://logs/godot.log, written by the game instead of the engine.
##
## The engine's own file log is off (project.godot: debug/file_logging/enable_file_logging.pc)
## because Debian's release build fills it with a false error each time a control leaves a
## container (EngineFalseErrors): 4,286 such lines in one 20-minute play trial, which bury a
## real error in the file a player would send with a bug report. This log writes what the
## engine's did, in the engine's format (prints, then "ERROR: message" and "   at: function
## (file:line)"), leaves out only that false report, and keeps the engine's rotation: the
## last run's log is renamed with its time and the oldest beyond MAX_FILES are removed.
## Called from any thread (the analysis prints from workers), so every write holds a lock.

## The log of the running game.
const LOG_PATH := "user://logs/godot.log"
## How many logs are kept, the running one included (the engine's default).
const MAX_FILES := 5
const _KIND_NAMES := ["ERROR", "WARNING", "SCRIPT ERROR", "SHADER ERROR"]

## False reports left out of the file so far.
var left_out := 0

var _file: FileAccess
var _lock := Mutex.new()


## Opens a fresh log at [param path] (its folder made if missing), after renaming the one
## there with its time and removing the oldest, so at most [param max_files] are kept.
func _init(path: String = LOG_PATH, max_files: int = MAX_FILES) -> void:
	var folder := path.get_base_dir()
	if not DirAccess.dir_exists_absolute(folder):
		DirAccess.make_dir_recursive_absolute(folder)
	_rotate(path, max_files)
	_file = FileAccess.open(path, FileAccess.WRITE)
	# the engine's own first lines come before any script runs: say what is running instead
	_write(heading(), true)


## The log's first line: the game's and the engine's versions and when it started.
static func heading() -> String:
	return (
		"Board Studio %s on Godot %s, started %s\n"
		% [
			ProjectSettings.get_setting("application/config/version", "?"),
			Engine.get_version_info().get("string", "?"),
			Time.get_datetime_string_from_system(false, true),
		]
	)


## Whether the file could be opened (a read-only user folder leaves the game without a log).
func is_open() -> bool:
	return _file != null


func _log_message(message: String, _error: bool) -> void:
	_write(message)


func _log_error(
	function: String,
	file: String,
	line: int,
	code: String,
	rationale: String,
	_editor_notify: bool,
	error_type: int,
	_script_backtraces: Array[ScriptBacktrace]
) -> void:
	if EngineFalseErrors.is_false_disconnect(function, file, code, rationale):
		_lock.lock()
		left_out += 1
		_lock.unlock()
		return
	var kind: String = _KIND_NAMES[clampi(error_type, 0, _KIND_NAMES.size() - 1)]
	var said := rationale if not rationale.is_empty() else code
	_write("%s: %s\n   at: %s (%s:%d)\n" % [kind, said, function, file, line], true)


func _write(text: String, flush: bool = false) -> void:
	_lock.lock()
	if _file != null:
		_file.store_string(text)
		# an error is flushed at once: the game may be about to stop
		if flush:
			_file.flush()
	_lock.unlock()


# The engine's scheme: godot.log becomes godot<its time>.log; only the newest are kept.
static func _rotate(path: String, max_files: int) -> void:
	var folder := path.get_base_dir()
	var stem := path.get_file().get_basename()
	var extension := path.get_extension()
	if FileAccess.file_exists(path):
		var stamp := Time.get_datetime_string_from_unix_time(FileAccess.get_modified_time(path))
		var kept := "%s/%s%s" % [folder, stem, stamp.replace(":", ".")]
		# two runs started in the same second (analysis workers) each keep their own, and a
		# later one always gets a higher number than any kept, so the age order holds
		var taken := 0
		for name in DirAccess.get_files_at(folder):
			if name.begins_with(kept.get_file()):
				taken = maxi(taken, _age_number(name))
		DirAccess.rename_absolute(path, _numbered(kept, taken + 1, extension))
	var old: Array[String] = []
	for name in DirAccess.get_files_at(folder):
		if name.begins_with(stem) and name.ends_with("." + extension) and name != path.get_file():
			old.append(name)
	# the time in each name, then its number within that second, sorts oldest first
	old.sort_custom(func(a: String, b: String) -> bool: return _age_key(a) < _age_key(b))
	while old.size() > max_files - 1:
		var oldest: String = old.pop_front()
		DirAccess.remove_absolute(folder.path_join(oldest))


static func _numbered(stem: String, number: int, extension: String) -> String:
	return "%s.%s" % [stem, extension] if number == 1 else "%s-%d.%s" % [stem, number, extension]


# A kept log's name as a key that sorts by age: its time, then its number.
static func _age_key(name: String) -> String:
	var base := name.get_basename()
	var number := _age_number(name)
	if number > 1:
		base = base.substr(0, base.rfind("-"))
	return "%s#%06d" % [base, number]


# A kept log's number within its second: 1 when its name has none.
static func _age_number(name: String) -> int:
	var base := name.get_basename()
	var ending := base.substr(base.rfind("-") + 1)
	return ending.to_int() if ending.is_valid_int() else 1
