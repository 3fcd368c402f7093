extends GutTest
## The hostile corpus in tests/fixtures/hostile_user_files/ read as settings.cfg and as
## save.cfg: object constructors, resource headers, NUL, UTF-16, NaN/INF, duplicate keys,
## wrong types, a newer version, plus generated huge and deeply nested files. No payload
## ever runs (the marker file never appears), nothing crashes, the values stay defaults or
## sane, a damaged file is kept byte for byte beside the new one, a newer one is untouched.

const CORPUS := "res://tests/fixtures/hostile_user_files/"
## The file every payload in the corpus writes if it is ever run as code.
const MARKER := "user://hostile_user_files_marker.txt"
const SCRATCH := "user://test_hostile_user_file.cfg"
## fixture -> what both loaders must make of it: "fine", "values" (some values refused, the
## rest read, the file kept aside), "damaged" (defaults, the file kept aside), "newer".
const EXPECTED := {
	"binary.cfg": "damaged",
	"bom_and_crlf.cfg": "fine",
	"control_characters.cfg": "values",
	"duplicate_keys.cfg": "values",
	"gd_resource_header.cfg": "damaged",
	"invalid_utf8.cfg": "damaged",
	"nan_and_inf.cfg": "values",
	"newer_version.cfg": "newer",
	"no_equals.cfg": "values",
	"not_a_settings_file.cfg": "damaged",
	"object_as_the_version.cfg": "damaged",
	"object_in_a_value.cfg": "values",
	"repeated_key_in_a_value.cfg": "values",
	"resource_constructor.cfg": "values",
	"two_statements_on_a_line.cfg": "values",
	"utf16.cfg": "damaged",
	"version_as_text.cfg": "damaged",
	"wrong_types.cfg": "values",
}
## The words each outcome's message must hold.
const MESSAGE_WORDS := {
	"values": "could not be used",
	"damaged": "could not be read",
	"newer": "newer version",
}


func before_each() -> void:
	DirAccess.remove_absolute(MARKER)


func after_each() -> void:
	DirAccess.remove_absolute(MARKER)
	_remove_scratch_files()


func _remove_scratch_files() -> void:
	var prefix := SCRATCH.get_file()
	for name in DirAccess.get_files_at("user://"):
		if name.begins_with(prefix):
			DirAccess.remove_absolute("user://" + name)


func _place(bytes: PackedByteArray) -> void:
	_remove_scratch_files()
	var file := FileAccess.open(SCRATCH, FileAccess.WRITE)
	file.store_buffer(bytes)
	file.close()


# The one file named SCRATCH.bad-*, or "" (asserting there is at most one).
func _kept_file() -> String:
	var kept := PackedStringArray()
	for name in DirAccess.get_files_at("user://"):
		if name.begins_with(SCRATCH.get_file() + ".bad-"):
			kept.append("user://" + name)
	assert_lte(kept.size(), 1, "one kept copy")
	return kept[0] if kept.size() == 1 else ""


func _check_settings_sane(settings: GameSettings, what: String) -> void:
	for value: float in [settings.master_volume, settings.sfx_volume]:
		assert_true(is_finite(value) and value >= 0.0 and value <= 1.0, "volume of %s" % what)
	var tilt := settings.tilt_sensitivity
	assert_true(
		tilt >= GameSettings.MIN_TILT_SENSITIVITY and tilt <= GameSettings.MAX_TILT_SENSITIVITY
	)
	assert_false(settings.events_for("pause").is_empty(), "%s: pause keeps a binding" % what)


# Loads `bytes` with `loader` (a Callable taking the path, returning the message) and checks the
# outcome; `saver` then writes the file as App does after a problem.
func _check_outcome(
	bytes: PackedByteArray, expected: String, loader: Callable, saver: Callable
) -> void:
	var what := (
		"%s (%s)"
		% [expected, (loader.get_object() as Object).get_script().resource_path.get_file()]
	)
	_place(bytes)
	var message: String = loader.call(SCRATCH)
	saver.call()
	assert_false(FileAccess.file_exists(MARKER), "%s: the payload never runs" % what)
	if expected == "fine":
		assert_eq(message, "", what)
		return
	assert_string_contains(message, MESSAGE_WORDS[expected], what)
	assert_string_contains(message, SCRATCH.get_file(), "%s: the message names the file" % what)
	var kept := _kept_file()
	if expected == "newer":
		assert_eq(kept, "", "%s: nothing moved" % what)
		assert_true(FileAccess.get_file_as_bytes(SCRATCH) == bytes, "%s: left untouched" % what)
		return
	assert_ne(kept, "", "%s: the damaged file is kept" % what)
	assert_string_contains(message, kept, "%s: the message names the kept file" % what)
	assert_true(FileAccess.get_file_as_bytes(kept) == bytes, "%s: kept byte for byte" % what)
	assert_eq(loader.call(SCRATCH), "", "%s: the rewritten file reads cleanly" % what)


func test_the_payload_is_live_for_configfile() -> void:
	# the control: without it, "no marker" could pass for a payload that never works
	ConfigFile.new().load(CORPUS + "object_in_a_value.cfg")
	assert_true(FileAccess.file_exists(MARKER), "this engine's ConfigFile runs the payload")


func test_every_fixture_is_listed() -> void:
	var names := Array(DirAccess.get_files_at(CORPUS))
	names.sort()
	var listed := EXPECTED.keys()
	listed.sort()
	assert_eq(names, listed, "every fixture has an expected outcome")


func test_every_fixture_as_settings() -> void:
	for name: String in EXPECTED:
		var settings := GameSettings.new()
		var bytes := FileAccess.get_file_as_bytes(CORPUS + name)
		_check_outcome(bytes, EXPECTED[name], settings.load_file, settings.save_file.bind(SCRATCH))
		_check_settings_sane(settings, name)


func test_every_fixture_as_save_data() -> void:
	for name: String in EXPECTED:
		var data := SaveData.new()
		var bytes := FileAccess.get_file_as_bytes(CORPUS + name)
		_check_outcome(bytes, EXPECTED[name], data.load_file, data.save)
		assert_eq(data.best_pachinko_balls("classic"), -1, name)
		assert_eq(data.best_maze_time("classic", false), -1.0, name)


func test_generated_monsters_as_settings_and_save_data() -> void:
	var head := "[meta]\nversion=1\n\n[audio]\n"
	# name -> [outcome as settings, outcome as save data (which has no [audio]), text]
	var monsters := {
		"ten megabytes": ["damaged", "damaged", "; padding\n".repeat(1024 * 1024)],
		"100000 nested [": ["values", "values", head + "master_volume=" + "[".repeat(100000)],
		"a 700 kB array": ["values", "fine", head + "master_volume=[" + "1,".repeat(350000) + "1]"],
		"100000 headers": ["damaged", "damaged", "[".repeat(100000)],
		"50000 lines of nonsense": ["values", "values", head + "?\n".repeat(50000)],
	}
	for name: String in monsters:
		var bytes: PackedByteArray = (monsters[name][2] as String).to_utf8_buffer()
		var started := Time.get_ticks_msec()
		var settings := GameSettings.new()
		_check_outcome(
			bytes, monsters[name][0], settings.load_file, settings.save_file.bind(SCRATCH)
		)
		var data := SaveData.new()
		_check_outcome(bytes, monsters[name][1], data.load_file, data.save)
		var spent := Time.get_ticks_msec() - started
		gut.p("%s: %d ms for both loaders" % [name, spent])
		assert_lt(spent, 5000, "%s read in well under 5 s" % name)


func test_a_too_large_file_says_so() -> void:
	_place(("; padding\n").repeat(200 * 1024).to_utf8_buffer())
	assert_string_contains(GameSettings.new().load_file(SCRATCH), "larger than the 1 MB")
