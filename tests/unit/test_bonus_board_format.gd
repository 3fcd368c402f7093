extends GutTest
## The bonus lines of a board file: written one item per line after the pockets, read back
## to the same board, absent from boards without them (older files keep their exact text),
## and every hostile value refused with the field named; the validator then refuses cups
## outside the ring, too shallow or overlapping.

const CLASSIC := "res://levels/pachinko/classic.board"


func _classic_text() -> String:
	return FileAccess.get_file_as_string(CLASSIC)


func _with_line(line: String) -> Dictionary:
	return BoardTextReader.read(_classic_text() + line + "\n")


func test_boards_without_bonus_pockets_keep_their_exact_text() -> void:
	for file in DirAccess.get_files_at("res://levels/pachinko"):
		if not file.ends_with(".board"):
			continue
		var text := FileAccess.get_file_as_string("res://levels/pachinko/" + file)
		var read := BoardTextReader.read(text)
		assert_true(read.has("level"), file)
		var level: BoardLevel = read["level"]
		if level.bonus_pockets.is_empty():
			assert_eq(BoardTextWriter.write(level), text, "%s written back byte for byte" % file)
			assert_false(text.contains('tulip":'), file)


func test_bonus_lines_round_trip() -> void:
	var text := _classic_text()
	text += '{"tulip": {"x": 100, "y": 300, "width": 24, "depth": 26, "payout": 5}}\n'
	text += '{"start_pocket": {"x": 350, "y": 200, "width": 24, "depth": 26, "payout": 3, '
	text += '"symbols": 4}}\n'
	text += '{"attacker": {"x": 350, "y": 600, "width": 60, "depth": 32, "payout": 15, '
	text += '"open_seconds": 6.5, "open_catches": 9}}\n'
	var read := BoardTextReader.read(text)
	assert_true(read.has("level"), str(read.get("error", "")))
	var level: BoardLevel = read["level"]
	assert_eq(level.bonus_pockets.size(), 3)
	var roles: Array[int] = []
	for spec in level.bonus_pockets:
		roles.append(spec.role)
	assert_eq(roles, [0, 1, 2], "start pockets, attackers, tulips")
	assert_eq(level.bonus_pockets[0].symbols, 4)
	assert_eq(level.bonus_pockets[1].open_seconds, 6.5)
	assert_eq(level.bonus_pockets[1].open_catches, 9)
	var written := BoardTextWriter.write(level)
	assert_eq(written.split("\n").size(), text.split("\n").size(), "one line per item")
	assert_string_contains(written, '{"start_pocket": {"id": 1, "x": 350, "y": 200, "width": 24')
	var again: BoardLevel = BoardTextReader.read(written)["level"]
	assert_eq(BoardTextWriter.write(again), written, "stable text")


func test_optional_fields_take_their_defaults() -> void:
	var line := '{"attacker": {"x": 350, "y": 600, "width": 60, "depth": 32, "payout": 15}}'
	var level: BoardLevel = _with_line(line)["level"]
	assert_eq(level.bonus_pockets[0].open_seconds, BonusPocketSpec.DEFAULT_OPEN_SECONDS)
	assert_eq(level.bonus_pockets[0].open_catches, BonusPocketSpec.DEFAULT_OPEN_CATCHES)


func test_hostile_bonus_values_are_refused_naming_the_field() -> void:
	var cup := '"x": 350, "y": 200, "width": 24, "depth": 26, "payout": 3'
	var cases := {
		'{"start_pocket": {%s, "symbols": 1}}' % cup: '"symbols"',
		'{"start_pocket": {%s, "symbols": 1e9}}' % cup: '"symbols"',
		'{"attacker": {%s, "open_seconds": -1}}' % cup: '"open_seconds"',
		'{"attacker": {%s, "open_seconds": 1e400}}' % cup: "finite",
		'{"attacker": {%s, "open_catches": 2.5}}' % cup: '"open_catches"',
		'{"tulip": {"x": 350, "y": 200, "width": 24, "depth": 26, "payout": 5000}}': '"payout"',
		'{"tulip": {"x": 350, "y": 200, "width": 2, "depth": 26, "payout": 5}}': '"width"',
		'{"tulip": {"x": "350", "y": 200, "width": 24, "depth": 26, "payout": 5}}': '"x"',
		'{"tulip": {"x": 350, "y": 200, "width": 24, "depth": 26}}': '"payout"',
		'{"tulip": {%s, "script": "res://x.gd"}}' % cup: '"script"',
		'{"tulip": {%s, "symbols": 3}}' % cup: '"symbols"',
		'{"tulip": [1, 2]}': "object",
		'{"tulips": []}': "one per line",
		'{"tulip": {%s}, "pin": {"x": 1, "y": 1}}' % cup: "alone",
	}
	for line: String in cases:
		var read := _with_line(line)
		assert_true(read.has("error"), "refused: %s" % line)
		if read.has("error"):
			assert_string_contains(read["error"], cases[line])


func test_too_many_bonus_pockets_are_refused() -> void:
	var lines := ""
	for i in 5:
		lines += (
			'{"start_pocket": {"x": %d, "y": 200, "width": 24, "depth": 26, "payout": 3}}\n'
			% (150 + 60 * i)
		)
	var read := BoardTextReader.read(_classic_text() + lines)
	assert_true(read.has("error"))
	assert_string_contains(read.get("error", ""), "start_pockets")


func _validated(specs: Array[BonusPocketSpec]) -> Array[String]:
	var level: BoardLevel = (load(CLASSIC) as BoardLevel).duplicate_level()
	level.bonus_pockets = specs
	var kinds: Array[String] = []
	for issue in BoardValidator.validate(level):
		if issue.kind.begins_with("bonus") or issue.kind == "bad_bonus":
			kinds.append(issue.kind + (" error" if issue.is_error() else ""))
	return kinds


func test_validator_refuses_bad_bonus_pockets() -> void:
	var role := BonusPocketSpec.Role
	var outside := BonusPocketSpec.of_role(role.TULIP, Vector2(350, 30), 24.0, 26.0, 5)
	assert_has(_validated([outside]), "bonus_outside error")
	var shallow := BonusPocketSpec.of_role(role.TULIP, Vector2(60, 350), 40.0, 10.0, 5)
	assert_has(_validated([shallow]), "bad_bonus error")
	var on_pins := BonusPocketSpec.of_role(role.TULIP, Vector2(350, 200), 24.0, 26.0, 5)
	assert_has(_validated([on_pins]), "bonus_blocked error", "classic's field pins fill it")
	var nan_spot := BonusPocketSpec.of_role(role.START, Vector2(NAN, 1), 24.0, 26.0, 5)
	assert_has(_validated([nan_spot]), "bad_bonus error")
	var no_start := BonusPocketSpec.of_role(role.ATTACKER, Vector2(350, 640), 40.0, 20.0, 5)
	assert_has(_validated([no_start]), "bonus_no_start")
	var wild := BonusPocketSpec.of_role(role.START, Vector2(350, 350), 24.0, 26.0, 5)
	wild.symbols = 40
	assert_has(_validated([wild]), "bad_bonus error")
