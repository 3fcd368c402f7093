extends GutTest
## The machine a pachinko board is dressed as (its "fascia" line): read and written as one
## line, classic when a file has none, an unknown machine refused by name, and every shipped
## board a machine of its own.

const CLASSIC_FILE := "res://levels/pachinko/classic.board"
const SHIPPED: Array[String] = [
	"res://levels/pachinko/classic.board",
	"res://levels/pachinko/windmills.board",
	"res://levels/pachinko/tulips.board",
	"res://levels/pachinko/fever.board",
	"res://levels/pachinko/hanami.board",
]


func _classic() -> BoardLevel:
	return BoardLoader.load_board(CLASSIC_FILE).level


func _with_fascia_line(text: String, line: String) -> String:
	var regex := RegEx.create_from_string('(?m)^\\{"fascia": .*\\}\\n')
	return regex.sub(text, line)


func test_every_machine_round_trips_as_one_line() -> void:
	var level := _classic()
	var before := BoardTextWriter.write(level).split("\n")
	for name in FasciaNames.NAMES:
		level.fascia = name
		var text := BoardTextWriter.write(level)
		assert_string_contains(text, '\n{"fascia": "%s"}\n' % name)
		var read := BoardTextReader.read(text)
		assert_false(read.has("error"), str(read.get("error", "")))
		if read.has("error"):
			continue
		var again: BoardLevel = read["level"]
		assert_eq(again.fascia, name)
		assert_eq(BoardTextWriter.write(again), text, "the same text twice")
		var after := text.split("\n")
		var changed := 0
		for i in after.size():
			if i >= before.size() or before[i] != after[i]:
				changed += 1
		assert_eq(after.size(), before.size(), "no line added or removed")
		assert_lte(changed, 1, "picking %s changes one line at most" % name)


func test_a_file_without_a_fascia_is_the_classic_machine() -> void:
	var level := _classic()
	level.fascia = "sakura"
	var text := _with_fascia_line(BoardTextWriter.write(level), "")
	assert_false(text.contains('"fascia"'))
	var read := BoardTextReader.read(text)
	assert_false(read.has("error"), str(read.get("error", "")))
	var again: BoardLevel = read.get("level")
	assert_eq(again.fascia, FasciaNames.CLASSIC)
	assert_eq(BoardLevel.new().fascia, FasciaNames.CLASSIC, "a board made in code too")


func test_an_unknown_machine_is_refused_with_its_name_and_the_choices() -> void:
	var text := _with_fascia_line(BoardTextWriter.write(_classic()), '{"fascia": "disco"}\n')
	var error := str(BoardTextReader.read(text).get("error", ""))
	assert_string_contains(error, '"fascia"')
	assert_string_contains(error, '"disco"')
	assert_string_contains(error, '"classic", "country", "garden", "neon" or "sakura"')
	var number := _with_fascia_line(BoardTextWriter.write(_classic()), '{"fascia": 3}\n')
	assert_string_contains(str(BoardTextReader.read(number).get("error", "")), '"fascia"')


func test_the_validator_refuses_an_unknown_machine_by_name() -> void:
	var level := _classic()
	level.fascia = "disco"
	var found := BoardValidator.errors(level).filter(
		func(issue: BoardIssue) -> bool: return issue.kind == "unknown_fascia"
	)
	assert_eq(found.size(), 1)
	if found.size() == 1:
		var issue: BoardIssue = found[0]
		assert_string_contains(issue.message, '"disco"')
		assert_string_contains(issue.message, '"sakura"')
	level.fascia = "neon"
	assert_eq(BoardValidator.errors(level).size(), 0)


func test_a_maze_has_no_fascia_line() -> void:
	var maze := BoardLoader.load_board("res://levels/maze/classic.board").level
	assert_false(BoardTextWriter.write(maze).contains('"fascia"'))
	var text := BoardTextWriter.write(maze) + '{"fascia": "classic"}\n'
	assert_string_contains(
		str(BoardTextReader.read(text).get("error", "")), 'unknown field "fascia"'
	)


func test_the_machine_is_looks_only_so_it_keeps_the_play_analysis() -> void:
	var level := _classic()
	var play := BoardTextWriter.play_hash(level)
	var content := BoardTextWriter.content_hash(level)
	level.fascia = "garden"
	assert_eq(BoardTextWriter.play_hash(level), play, "the analysis cache still fits")
	assert_ne(BoardTextWriter.content_hash(level), content, "the file did change")


func test_every_shipped_board_wears_a_machine_of_its_own() -> void:
	var worn := {}
	for path in SHIPPED:
		assert_string_contains(FileAccess.get_file_as_string(path), '{"fascia": ')
		var level := BoardLoader.load_board(path).level
		assert_not_null(level, path)
		if level == null:
			continue
		assert_false(worn.has(level.fascia), "%s shares %s" % [path, level.fascia])
		worn[level.fascia] = path
	assert_eq(worn.size(), FasciaNames.NAMES.size(), "all five machines are worn")
	assert_eq(_classic().fascia, FasciaNames.CLASSIC, "Classic keeps the chapter's machine")
