extends GutTest
## The house rule for scripts/physics, checked: no file over CodeSize.MAX_FILE_LINES lines
## and no function over CodeSize.MAX_FUNC_LINES (from its `func` line to its last non-blank
## line), except the kernels: hot loops written out on purpose in one file
## (docs/architecture.md, "Kernels"), whose copies of readable rules are pinned by their own
## tests instead. test_house_code_size holds every other script to the same rule.

const CodeSize := preload("res://tests/helpers/code_size.gd")
const FOLDER := "res://scripts/physics/"
const ARCHITECTURE := "res://docs/architecture.md"


func _scripts() -> PackedStringArray:
	var out := PackedStringArray()
	for file: String in DirAccess.get_files_at(FOLDER):
		if file.ends_with(".gd"):
			out.append(FOLDER + file)
	return out


func test_the_measure_counts_a_function_to_its_last_line() -> void:
	var text := "func a() -> void:\n\tpass\n\tpass\n\n\n## doc\nfunc b() -> int:\n\treturn 1\n"
	var found := CodeSize.functions_of(text.split("\n"))
	assert_eq(found, [Vector2i(0, 3), Vector2i(6, 2)] as Array[Vector2i])


func test_no_physics_file_or_function_is_too_long() -> void:
	var scripts := _scripts()
	assert_gt(scripts.size(), 10, "the physics scripts are found")
	for path: String in scripts:
		var problems := CodeSize.problems(path)
		assert_eq(problems, PackedStringArray(), "%s keeps the house rule" % path)


func test_every_kernel_exists_and_is_listed_as_one() -> void:
	var doc: String = FileAccess.get_file_as_string(ARCHITECTURE)
	var section: String = doc.get_slice("## Kernels", 1).get_slice("\n## ", 0)
	assert_ne(section, "", "docs/architecture.md has a Kernels section")
	for path: String in CodeSize.KERNELS:
		assert_true(FileAccess.file_exists(path), "%s exists" % path)
		var named: String = "`%s`" % path.trim_prefix("res://")
		assert_true(section.contains(named), "%s is listed under Kernels" % named)
