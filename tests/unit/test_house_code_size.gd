extends GutTest
## The house rule for every project script, not only scripts/physics (whose own test also
## checks the kernels are listed): no file over CodeSize.MAX_FILE_LINES lines and no
## function over CodeSize.MAX_FUNC_LINES, the kernels (CodeSize.KERNELS) excepted. GUT
## (addons/gut) is a library, not ours; tests/ is not held to the rule.

const CodeSize := preload("res://tests/helpers/code_size.gd")
## Where the project's scripts live.
const FOLDERS: Array[String] = [
	"res://scripts/", "res://scenes/", "res://addons/board_editor/", "res://tools/"
]


func test_the_scripts_are_found_in_every_folder() -> void:
	for folder: String in FOLDERS:
		assert_gt(CodeSize.scripts_under(folder).size(), 0, "%s has scripts" % folder)
	var all := CodeSize.scripts_under("res://scripts/")
	assert_has(all, "res://scripts/board/item_kinds/item_kind.gd", "subfolders are searched")


func test_a_long_script_breaks_the_rule() -> void:
	var path := "user://house_rule_probe.gd"
	var text := "func long() -> void:\n" + "\tpass\n".repeat(CodeSize.MAX_FUNC_LINES)
	text += "\n".repeat(CodeSize.MAX_FILE_LINES)
	var file := FileAccess.open(path, FileAccess.WRITE)
	file.store_string(text + "\n")
	file.close()
	var problems := CodeSize.problems(path)
	DirAccess.remove_absolute(ProjectSettings.globalize_path(path))
	assert_eq(problems.size(), 2, "the file and its function are too long: %s" % [problems])


func test_no_project_script_or_function_is_too_long() -> void:
	for folder: String in FOLDERS:
		for path: String in CodeSize.scripts_under(folder):
			assert_eq(
				CodeSize.problems(path), PackedStringArray(), "%s keeps the house rule" % path
			)
