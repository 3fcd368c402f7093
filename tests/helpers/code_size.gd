extends RefCounted
## The house rule's measure, shared by the tests that check it (test_physics_code_size,
## test_house_code_size): no script over MAX_FILE_LINES lines and no function over
## MAX_FUNC_LINES (from its `func` line to its last non-blank line), except the kernels:
## hot loops written out on purpose in one file (docs/architecture.md, "Kernels").

const MAX_FILE_LINES := 400
const MAX_FUNC_LINES := 80
## The kernels, exempt from both limits. Each must be listed as a kernel in
## docs/architecture.md too (test_physics_code_size checks it), so the exemption is never
## silent.
const KERNELS: Array[String] = ["res://scripts/physics/ball_mover.gd"]


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


## What breaks the rule in the script at `path` ("res://..."), one line each: the file's
## length, each function's; empty for a kernel or a script within the limits.
static func problems(path: String) -> PackedStringArray:
	var out := PackedStringArray()
	if path in KERNELS:
		return out
	var lines: PackedStringArray = FileAccess.get_file_as_string(path).split("\n")
	var count: int = lines.size() - (1 if lines[lines.size() - 1] == "" else 0)
	if count > MAX_FILE_LINES:
		out.append("%s has %d lines (most %d)" % [path, count, MAX_FILE_LINES])
	for f: Vector2i in functions_of(lines):
		if f.y > MAX_FUNC_LINES:
			var what := "%s:%d %s is %d lines" % [path, f.x + 1, lines[f.x].left(40), f.y]
			out.append("%s (most %d)" % [what, MAX_FUNC_LINES])
	return out


## Every .gd script under `folder` ("res://.../") and its subfolders, in name order,
## leaving out any folder whose path is in `skipped`.
static func scripts_under(folder: String, skipped: PackedStringArray = []) -> PackedStringArray:
	var out := PackedStringArray()
	if folder in skipped:
		return out
	for file: String in DirAccess.get_files_at(folder):
		if file.ends_with(".gd"):
			out.append(folder + file)
	for sub: String in DirAccess.get_directories_at(folder):
		out.append_array(scripts_under(folder + sub + "/", skipped))
	return out
