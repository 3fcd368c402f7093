extends GutTest
## Windmills in board files (`windmill` lines): written one per line after the bonus
## pockets, read back to the same board, refused with the field named when a value is bad;
## the validator's messages for windmills that do not fit; the factory builds them.

const CLASSIC := "res://levels/pachinko/classic.board"


## Classic's ring, rail and tuning with no pins or pockets: room for windmills anywhere.
func _open_board() -> BoardLevel:
	var level: BoardLevel = BoardTextReader.read(FileAccess.get_file_as_string(CLASSIC))["level"]
	level.pins = PackedVector2Array()
	level.pin_pocket = PackedInt32Array()
	level.pin_special = PackedByteArray()
	level.pin_ids = PackedInt32Array()
	level.pockets = []
	level.pocket_ids = PackedInt32Array()
	level.bonus_pockets = []
	return level


## The validator's messages about windmills, one a line.
func _messages(level: BoardLevel) -> String:
	var texts := PackedStringArray()
	for issue in BoardValidator.validate(level):
		if issue.message.contains("Windmill"):
			texts.append("%s: %s" % ["error" if issue.is_error() else "warning", issue.message])
	return "\n".join(texts)


func test_windmill_lines_round_trip() -> void:
	var level := _open_board()
	level.windmills = [
		WindmillSpec.driven(Vector2(300, 250), 4, 22.0, -135.5),
		WindmillSpec.spinning_free(Vector2(420, 300), 3, 26.0, 180.0),
	]
	var text := BoardTextWriter.write(level)
	assert_string_contains(
		text,
		'{"windmill": {"id": 1, "x": 300, "y": 250, "blades": 4, "length": 22, "speed": -135.5}}'
	)
	assert_string_contains(
		text,
		'{"windmill": {"id": 2, "x": 420, "y": 300, "blades": 3, "length": 26, "friction": 180}}'
	)
	var read := BoardTextReader.read(text)
	assert_true(read.has("level"), str(read.get("error", "")))
	var again: BoardLevel = read["level"]
	assert_eq(again.windmills.size(), 2)
	assert_false(again.windmills[0].free_spin)
	assert_eq(again.windmills[0].speed, -135.5)
	assert_true(again.windmills[1].free_spin)
	assert_eq(again.windmills[1].friction, 180.0)
	assert_eq(again.windmills[1].blades, 3)
	assert_eq(BoardTextWriter.write(again), text, "stable text")


func test_boards_without_windmills_write_no_windmill_line() -> void:
	var text := FileAccess.get_file_as_string(CLASSIC)
	var level: BoardLevel = BoardTextReader.read(text)["level"]
	assert_eq(BoardTextWriter.write(level), text)
	assert_false(text.contains("windmill"))


func test_bad_windmill_lines_are_refused_with_the_problem_named() -> void:
	var base := FileAccess.get_file_as_string(CLASSIC)
	var cases := {
		'{"windmill": {"x": 300, "y": 250, "blades": 4, "length": 22}}':
		'needs "speed" (a driven wheel, degrees a second) or "friction"',
		'{"windmill": {"x": 300, "y": 250, "blades": 4, "length": 22, "speed": 9, "friction": 9}}':
		"not both",
		'{"windmill": {"x": 300, "y": 250, "blades": 1, "length": 22, "speed": 90}}':
		'"blades" must be between 2 and 12, got 1',
		'{"windmill": {"x": 300, "y": 250, "blades": 4, "length": 500, "speed": 90}}':
		'"length" must be between 8 and 120, got 500',
		'{"windmill": {"x": 300, "y": 250, "blades": 4, "length": 22, "speed": "fast"}}':
		'"speed" must be a number',
		'{"windmill": {"x": 300, "y": 250, "blades": 4, "length": 22, "friction": -1}}':
		'"friction" must be between 0 and 36000, got -1',
		'{"windmill": {"x": 300, "y": 250, "blades": 4, "length": 22, "speed": 9, "colour": 1}}':
		'unknown field "colour"',
	}
	for line: String in cases:
		var read := BoardTextReader.read(base + line + "\n")
		assert_true(read.has("error"), line)
		var error: String = read.get("error", "")
		assert_string_contains(error, "windmills item 1: ")
		assert_string_contains(error, cases[line])


func test_a_fitting_windmill_passes_the_check() -> void:
	var level := _open_board()
	level.windmills = [WindmillSpec.driven(Vector2(350, 300), 4, 22.0, 120.0)]
	assert_eq(_messages(level), "")


func test_the_check_names_windmills_that_do_not_fit() -> void:
	var level := _open_board()
	var too_fast := WindmillSpec.driven(Vector2(250, 250), 4, 30.0, 3500.0)
	var outside := WindmillSpec.driven(Vector2(350, 660), 4, 22.0, 90.0)
	var first := WindmillSpec.driven(Vector2(400, 420), 4, 22.0, 90.0)
	var crossing := WindmillSpec.driven(Vector2(430, 420), 4, 22.0, 90.0)
	var no_friction := WindmillSpec.spinning_free(Vector2(300, 160), 4, 22.0, 0.0)
	level.windmills = [too_fast, outside, first, crossing, no_friction]
	level.pins = PackedVector2Array([Vector2(262, 250)])
	level.pin_pocket = PackedInt32Array([-1])
	level.pin_special = PackedByteArray([0])
	level.pin_ids = PackedInt32Array([7])
	var text := _messages(level)
	assert_string_contains(
		text,
		(
			"error: Windmill 1 moves its blade tips at 1954.8 px/s, faster than a ball can go"
			+ " (1600 px/s): at most 2864 degrees a second."
		)
	)
	assert_string_contains(text, "error: Windmill 2's blades reach 334 px from the ring's centre")
	assert_string_contains(text, "error: Windmills 3 and 4 overlap: their blades would cross.")
	assert_string_contains(
		text, "warning: Windmill 5 spins free with no friction: once struck it never stops."
	)
	# The too-fast wheel is not checked further; the pin is then only inside none.
	level.windmills = [WindmillSpec.driven(Vector2(250, 250), 4, 22.0, 90.0)]
	assert_string_contains(
		_messages(level), "error: Windmill 1's blades would sweep through pin 7."
	)
	level.pins = PackedVector2Array([Vector2(280, 250)])
	assert_string_contains(
		_messages(level),
		"warning: Windmill 1 leaves a 4.5 px gap to pin 7; a ball (10 px) would jam between them."
	)


func test_the_check_refuses_a_windmill_over_a_pocket() -> void:
	var level := _open_board()
	level.pockets = [PocketSpec.create(Vector2(350, 500), 24.0, 26.0, 5)]
	level.windmills = [WindmillSpec.driven(Vector2(350, 480), 4, 22.0, 90.0)]
	assert_string_contains(_messages(level), "Windmill 1's blades would sweep into pocket 1.")


func test_the_factory_builds_each_windmill_in_order() -> void:
	var level := _open_board()
	level.windmills = [
		WindmillSpec.driven(Vector2(300, 250), 4, 22.0, 90.0),
		WindmillSpec.spinning_free(Vector2(420, 300), 3, 26.0, 180.0),
	]
	var world := BoardWorldFactory.build(level)
	assert_eq(world.shapes.windmill_count(), 2)
	assert_almost_eq(world.shapes.get_windmill_speed(0), deg_to_rad(90.0), 1e-9)
	assert_eq(world.shapes.get_windmill_speed(1), 0.0, "a free wheel starts at rest")
	world.step(1.0 / 120.0)
	assert_almost_eq(world.shapes.get_windmill_angle(0), deg_to_rad(90.0) / 120.0, 1e-9)
