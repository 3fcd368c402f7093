extends GutTest
## The house rule for scripts/physics, checked: no file over MAX_FILE_LINES lines and no
## function over MAX_FUNC_LINES (from its `func` line to its last non-blank line), except
## the kernels: hot loops written out on purpose in one file (docs/architecture.md,
## "Kernels"), whose copies of readable rules are pinned by their own tests instead.

const FOLDER := "res://scripts/physics/"
const MAX_FILE_LINES := 400
const MAX_FUNC_LINES := 80
## The kernels, exempt from both limits. Each must be listed as a kernel in
## docs/architecture.md too (checked below), so the exemption is never silent.
const KERNELS: Array[String] = ["res://scripts/physics/ball_mover.gd"]
const ARCHITECTURE := "res://docs/architecture.md"


func _scripts() -> PackedStringArray:
	var out := PackedStringArray()
	for file: String in DirAccess.get_files_at(FOLDER):
		if file.ends_with(".gd"):
			out.append(FOLDER + file)
	return out


## Each function of `lines` as [first line index, line count].
static func functions_of(lines: PackedStringArray) -> Array[Vector2i]:
	var out: Array[Vector2i] = []
	var start := -1
	var last := -1
	for k: int in lines.size():
		var line: String = lines[k]
		var top_level: bool = (
			line != "" and not line.begins_with("\t") and not line.begins_with(" ")
		)
		if top_level and not line.begins_with("#"):
			if start >= 0:
				out.append(Vector2i(start, last - start + 1))
				start = -1
			if line.begins_with("func ") or line.begins_with("static func "):
				start = k
		if line.strip_edges() != "" and not top_level:
			last = k
		elif start == k:
			last = k
	if start >= 0:
		out.append(Vector2i(start, last - start + 1))
	return out


func test_the_measure_counts_a_function_to_its_last_line() -> void:
	var text := "func a() -> void:\n\tpass\n\tpass\n\n\n## doc\nfunc b() -> int:\n\treturn 1\n"
	var found := functions_of(text.split("\n"))
	assert_eq(found, [Vector2i(0, 3), Vector2i(6, 2)] as Array[Vector2i])


func test_no_physics_file_or_function_is_too_long() -> void:
	var scripts := _scripts()
	assert_gt(scripts.size(), 10, "the physics scripts are found")
	for path: String in scripts:
		if path in KERNELS:
			continue
		var lines: PackedStringArray = FileAccess.get_file_as_string(path).split("\n")
		var count: int = lines.size() - (1 if lines[lines.size() - 1] == "" else 0)
		assert_lte(count, MAX_FILE_LINES, "%s has %d lines" % [path, count])
		for f: Vector2i in functions_of(lines):
			var what := "%s:%d %s is %d lines" % [path, f.x + 1, lines[f.x].left(40), f.y]
			assert_lte(f.y, MAX_FUNC_LINES, what)


func test_every_kernel_exists_and_is_listed_as_one() -> void:
	var doc: String = FileAccess.get_file_as_string(ARCHITECTURE)
	var section: String = doc.get_slice("## Kernels", 1).get_slice("\n## ", 0)
	assert_ne(section, "", "docs/architecture.md has a Kernels section")
	for path: String in KERNELS:
		assert_true(FileAccess.file_exists(path), "%s exists" % path)
		var named: String = "`%s`" % path.trim_prefix("res://")
		assert_true(section.contains(named), "%s is listed under Kernels" % named)
