extends GutTest
## Mangled board files (cut, spliced, truncated) are refused with a message or load as a
## valid board: never an engine parse error, never a crash. The files are written to
## build/ (ignored by git and by the editor) because only res:// boards are loaded.

const LegacyBoardLoader := preload("res://tools/legacy_boards/legacy_board_loader.gd")
const DIR := "res://build/test_board_fuzz"
const SOURCES := ["tiny_pachinko", "tiny_maze", "v0_pachinko"]
const CASES_PER_SOURCE := 40
const TOKENS := [
	"(", ")", "[", "]", '"', "=", "\n", ",", "nan", "Object(Node,", 'ExtResource("9")', "{", " "
]


func before_all() -> void:
	DirAccess.make_dir_recursive_absolute(ProjectSettings.globalize_path(DIR))
	var ignore := FileAccess.open(DIR + "/.gdignore", FileAccess.WRITE)
	if ignore != null:
		ignore.close()


func after_all() -> void:
	for file_name in DirAccess.get_files_at(DIR):
		DirAccess.remove_absolute(ProjectSettings.globalize_path(DIR + "/" + file_name))
	DirAccess.remove_absolute(ProjectSettings.globalize_path(DIR + "/.gdignore"))
	DirAccess.remove_absolute(ProjectSettings.globalize_path(DIR))


func test_mangled_files_are_refused_cleanly() -> void:
	var rng := RandomNumberGenerator.new()
	rng.seed = 2024
	var refused := 0
	for source: String in SOURCES:
		var base := FileAccess.get_file_as_string("res://tests/fixtures/boards/%s.tres" % source)
		assert_false(base.is_empty(), source)
		for n in CASES_PER_SOURCE:
			var path := "%s/%s_%d.tres" % [DIR, source, n]
			var file := FileAccess.open(path, FileAccess.WRITE)
			file.store_string(_mangle(base, rng))
			file.close()
			var loaded := LegacyBoardLoader.load_board(path)
			if loaded.ok():
				assert_eq(BoardValidator.errors(loaded.level).size(), 0, path)
			else:
				refused += 1
				assert_string_contains(loaded.error, path)
	assert_gt(refused, CASES_PER_SOURCE, "most mangled files are refused")


func _mangle(text: String, rng: RandomNumberGenerator) -> String:
	for m in rng.randi_range(1, 3):
		var at := rng.randi_range(0, text.length() - 1)
		match rng.randi_range(0, 3):
			0:
				text = text.substr(0, at) + text.substr(at + rng.randi_range(1, 8))
			1:
				text = (
					text.substr(0, at)
					+ str(TOKENS[rng.randi_range(0, TOKENS.size() - 1)])
					+ text.substr(at)
				)
			2:
				text = text.substr(0, at)
			_:
				var lines := text.split("\n")
				lines.remove_at(rng.randi_range(0, lines.size() - 1))
				text = "\n".join(lines)
	return text
