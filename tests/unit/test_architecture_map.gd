extends GutTest
## docs/architecture.md stays a short, true map: at most MAX_LINES lines, and every row of
## its "Where to look first" table names a file that exists and holds the function it names;
## every README it sends a reader to exists.

const ARCHITECTURE := "res://docs/architecture.md"
const MAX_LINES := 300


func _text() -> String:
	return FileAccess.get_file_as_string(ARCHITECTURE)


# The rows of the "Where to look first" table: [question, file, function cell].
func _guess_rows() -> Array[PackedStringArray]:
	var rows: Array[PackedStringArray] = []
	var inside := false
	for line in _text().split("\n"):
		if line.begins_with("## "):
			inside = line == "## Where to look first"
			continue
		if not inside or not line.begins_with("| Where"):
			continue
		var cells := line.trim_prefix("|").trim_suffix("|").split("|")
		rows.append(PackedStringArray([cells[0].strip_edges(), cells[1], cells[2]]))
	return rows


# The first `name` in backticks in a table cell.
static func _first_code(cell: String) -> String:
	var start := cell.find("`")
	var end := cell.find("`", start + 1)
	return cell.substr(start + 1, end - start - 1) if start >= 0 and end > start else ""


func test_the_map_is_short() -> void:
	var lines := _text().split("\n").size()
	assert_lte(lines, MAX_LINES, "docs/architecture.md has %d lines" % lines)


func test_every_guess_names_a_file_that_holds_its_function() -> void:
	var rows := _guess_rows()
	assert_gte(rows.size(), 10, "the table is there")
	for row in rows:
		var path := "res://" + _first_code(row[1])
		var function_name := _first_code(row[2])
		assert_true(FileAccess.file_exists(path), "%s: %s exists" % [row[0], path])
		var source := FileAccess.get_file_as_string(path)
		var defines := (
			source.contains("\nfunc %s(" % function_name)
			or source.contains("\nstatic func %s(" % function_name)
		)
		assert_true(defines, "%s: %s holds func %s" % [row[0], path, function_name])


func test_every_readme_it_points_to_exists() -> void:
	var text := _text()
	var at := text.find("README.md`")
	var found := 0
	while at >= 0:
		var start := text.rfind("`", at - 1)
		var path := text.substr(start + 1, at + "README.md".length() - start - 1)
		assert_true(FileAccess.file_exists("res://" + path), "%s exists" % path)
		found += 1
		at = text.find("README.md`", at + 1)
	assert_gte(found, 10, "the map sends each part to its README")
