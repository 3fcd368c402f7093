extends GutTest
## A reviewable board file: typing a new value into any field of any item in the Selection
## panel and saving changes exactly one line of the file, the line of that item (a pocket's
## rim pins are stamped from the pocket, not stored, so a pocket edit never renumbers pins).

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const ItemProperties := preload("res://addons/board_editor/core/item_properties.gd")
const EditCommands := preload("res://addons/board_editor/core/edit_commands.gd")

## How far each field is moved: small enough to stay valid, large enough to show in the file.
const STEP := {
	"x": 3.0,
	"y": 2.0,
	"ax": 4.0,
	"ay": 4.0,
	"bx": -4.0,
	"by": -4.0,
	"width": 4.0,
	"depth": 6.0,
	"payout": 1.0,
	"radius": 2.0,
	"symbols": -1.0,  # Fever's reels have 9, the most a reel may have
	"open_seconds": 1.0,
	"open_catches": 1.0,
	"blades": 1.0,
	"length": 3.0,
	"free": 1.0,
	"speed": 30.0,
	"friction": 20.0,
}


func _load(path: String) -> BoardLevel:
	if not path.begins_with("res://"):
		var read: Dictionary = BoardTextReader.read(path)  # board text (a board made in the test)
		assert_not_null(read.get("level"), str(read.get("error", "")))
		return read.get("level")
	var result := BoardLoader.load_board(path)
	assert_not_null(result.level, result.error)
	return result.level


# The lines that differ between two texts with the same number of lines (every line when
# the counts differ, so the test fails loudly).
func _changed_lines(before: String, after: String) -> PackedStringArray:
	var a := before.split("\n")
	var b := after.split("\n")
	if a.size() != b.size():
		return b
	var changed := PackedStringArray()
	for i in a.size():
		if a[i] != b[i]:
			changed.append(b[i])
	return changed


# Edits every field of `item` one at a time (each from the board as loaded from `path`, a
# file or board text) and checks that the saved text changes in one line, which
# `line_start` begins.
func _check_each_field(path: String, item: Vector2i, line_start: String) -> void:
	var fields := ItemProperties.values_of(_load(path), item)
	assert_false(fields.is_empty(), "%s has item %s" % [path, item])
	for key: String in fields:
		var level := _load(path)
		var session := BoardEditSession.new(level)
		var before := BoardTextWriter.write(level)
		var value: float = fields[key]
		var action := ItemProperties.action_for(level, item, key, value + STEP[key])
		assert_not_null(action, "%s: field %s gives an edit" % [path, key])
		if action == null:
			continue
		session.commit(action)
		var changed := _changed_lines(before, BoardTextWriter.write(level))
		assert_eq(changed.size(), 1, "%s: setting %s of %s changes one line" % [path, key, item])
		if changed.size() == 1:
			assert_true(
				changed[0].begins_with(line_start),
				(
					"%s: the changed line is the item's own (%s...): %s"
					% [path, line_start, changed[0]]
				)
			)
		var read: Dictionary = BoardTextReader.read(BoardTextWriter.write(level))
		assert_not_null(read.get("level"), "%s: the edited file reads back" % path)


func test_each_field_of_a_pin_changes_only_its_line() -> void:
	var level := _load("res://levels/pachinko/classic.board")
	var id := ItemIds.of(level, "pins", 5)
	_check_each_field(
		"res://levels/pachinko/classic.board",
		BoardItems.make(BoardItems.Kind.PIN, 5),
		'{"pin": {"id": %d, ' % id
	)


func test_each_field_of_a_pocket_changes_only_its_line() -> void:
	var level := _load("res://levels/pachinko/classic.board")
	var id := ItemIds.of(level, "pockets", 1)
	_check_each_field(
		"res://levels/pachinko/classic.board",
		BoardItems.make(BoardItems.Kind.POCKET, 1),
		'{"pocket": {"id": %d, ' % id
	)


func test_a_payout_change_is_a_one_line_diff() -> void:
	var level := _load("res://levels/pachinko/classic.board")
	var session := BoardEditSession.new(level)
	var before := BoardTextWriter.write(level)
	var pocket := BoardItems.make(BoardItems.Kind.POCKET, 1)
	session.commit(ItemProperties.action_for(level, pocket, "payout", 4.0))
	var changed := _changed_lines(before, BoardTextWriter.write(level))
	assert_eq(
		changed,
		PackedStringArray(
			['{"pocket": {"id": 2, "x": 215, "y": 390, "width": 22, "depth": 24, "payout": 4}}']
		)
	)


func test_each_field_of_each_bonus_pocket_changes_only_its_line() -> void:
	var path := "res://levels/pachinko/fever.board"
	var level := _load(path)
	var seen := {}
	for i in level.bonus_pockets.size():
		var spec := level.bonus_pockets[i]
		if seen.has(spec.role):
			continue
		seen[spec.role] = true
		var start := '{"%s": {"id": %d, ' % [spec.role_key(), ItemIds.of_bonus(level, i)]
		_check_each_field(path, BoardItems.make(BoardItems.Kind.BONUS, i), start)
	assert_eq(seen.size(), 3, "Fever has every bonus role")


func test_each_field_of_each_maze_item_changes_only_its_line() -> void:
	var path := "res://levels/maze/classic.board"
	var level := _load(path)
	var cases := [
		[BoardItems.Kind.WALL, "walls", "wall"],
		[BoardItems.Kind.HOLE, "holes", "hole"],
		[BoardItems.Kind.START, "ball_starts", "ball_start"],
	]
	for entry: Array in cases:
		var id := ItemIds.of(level, entry[1], 1)
		_check_each_field(path, BoardItems.make(entry[0], 1), '{"%s": {"id": %d, ' % [entry[2], id])


func test_goal_fields_change_only_their_header_line() -> void:
	var path := "res://levels/maze/classic.board"
	var goal := BoardItems.make(BoardItems.Kind.GOAL, 0)
	var level := _load(path)
	for key: String in ["x", "y", "radius"]:
		level = _load(path)
		var session := BoardEditSession.new(level)
		var before := BoardTextWriter.write(level)
		var fields := ItemProperties.values_of(level, goal)
		var value: float = fields[key]
		session.commit(ItemProperties.action_for(level, goal, key, value + STEP[key]))
		var changed := _changed_lines(before, BoardTextWriter.write(level))
		var line := '{"goal_radius": ' if key == "radius" else '{"goal_center": '
		assert_eq(changed.size(), 1, "goal %s: one line" % key)
		if changed.size() == 1:
			assert_true(changed[0].begins_with(line), changed[0])


func test_editing_a_pocket_keeps_every_pin_id() -> void:
	var level := _load("res://levels/pachinko/tulips.board")
	var session := BoardEditSession.new(level)
	var ids_before := _field_pin_ids(level)
	var pocket := BoardItems.make(BoardItems.Kind.POCKET, 0)
	var width: float = ItemProperties.values_of(level, pocket)["width"]
	session.commit(ItemProperties.action_for(level, pocket, "width", width + 10.0))
	assert_eq(_field_pin_ids(level), ids_before, "a wider pocket renumbers no pin")
	session.commit(ItemProperties.action_for(level, pocket, "depth", 60.0))
	assert_eq(_field_pin_ids(level), ids_before, "a deeper one neither")
	session.history.undo()
	session.history.undo()
	assert_eq(_field_pin_ids(level), ids_before, "nor the undo")


func test_files_with_stored_rim_pins_still_load_the_same_board() -> void:
	var level := _load("res://levels/pachinko/classic.board")
	var text := BoardTextWriter.write(level)
	# An older file: the first pocket's rim pins written out with their pocket index.
	var rim := PocketStamp.rim_pins(level.pockets[0], level.pin_radius, level.ball_radius)
	var lines := PackedStringArray()
	for i in rim.size():
		lines.append(
			(
				'{"pin": {"id": %d, "x": %s, "y": %s, "pocket": 0%s}}'
				% [
					900 + i,
					BoardTextWriter.number(rim[i].x),
					BoardTextWriter.number(rim[i].y),
					', "special": true' if i == rim.size() - 1 else ""
				]
			)
		)
	var old := text.replace('{"pocket": {"id": 1,', "\n".join(lines) + '\n{"pocket": {"id": 1,')
	var read: Dictionary = BoardTextReader.read(old)
	var back: BoardLevel = read.get("level")
	assert_not_null(back, str(read.get("error", "")))
	if back != null:
		assert_eq(back.pins, level.pins, "the same pins, stamped from the pockets")
		assert_eq(BoardTextWriter.write(back), text, "and saved, the stored rim pins are gone")


func test_a_rim_pin_is_named_by_its_pocket() -> void:
	var level := _load("res://levels/pachinko/classic.board")
	var rim := BoardItems.pocket_pins(level, 2)
	assert_eq(ItemIds.of(level, "pins", rim[0]), 0, "a rim pin has no id of its own")
	assert_eq(ItemIds.pin_label(level, rim[0]), "a pin of pocket 3's rim")


func _field_pin_ids(level: BoardLevel) -> Dictionary:
	var by_place := {}
	for i in level.pins.size():
		if not ItemIds.is_rim_pin(level, i):
			by_place[ItemIds.of(level, "pins", i)] = level.pins[i]
	return by_place


func test_a_pocket_outside_the_ring_is_one_error_naming_the_pocket() -> void:
	var level := _load("res://levels/pachinko/classic.board")
	var session := BoardEditSession.new(level)
	var pocket := BoardItems.make(BoardItems.Kind.POCKET, 1)
	session.commit(ItemProperties.action_for(level, pocket, "x", 15.0))
	var errors := BoardValidator.errors(level)
	var messages := PackedStringArray()
	for issue in errors:
		messages.append(issue.message)
	assert_eq(messages, PackedStringArray(["Pocket 2's rim is outside the ring."]))


func test_a_duplicated_pocket_never_overlaps_its_original() -> void:
	var level := _load("res://levels/pachinko/classic.board")
	var session := BoardEditSession.new(level)
	var errors_before := BoardValidator.errors(level).size()
	session.select([BoardItems.make(BoardItems.Kind.POCKET, 0)] as Array[Vector2i])
	assert_true(EditCommands.duplicate_selection(session))
	assert_eq(level.pockets.size(), 6)
	var gap := level.pockets[5].position.x - level.pockets[0].position.x
	assert_gte(gap, level.pockets[0].width + level.ball_radius * 2.0, "a ball clear of it")
	var nearest := INF
	for a in BoardItems.pocket_pins(level, 0):
		for b in BoardItems.pocket_pins(level, 5):
			nearest = minf(nearest, level.pins[a].distance_to(level.pins[b]))
	var clear := nearest - level.pin_radius * 2.0
	assert_gte(clear, level.ball_radius * 2.0, "the rims leave a ball's width between them")
	assert_eq(BoardValidator.errors(level).size(), errors_before)


func test_each_field_of_a_windmill_changes_only_its_line() -> void:
	var level := _load("res://levels/pachinko/classic.board")
	var wheel := WindmillSpec.new()
	wheel.position = Vector2(350, 470)
	level.windmills = [wheel] as Array[WindmillSpec]
	ItemIds.fill(level)
	var text := BoardTextWriter.write(level)
	_check_each_field(text, BoardItems.make(BoardItems.Kind.WINDMILL, 0), '{"windmill": {"id": 1, ')
