extends GutTest
## Every row of the ItemKinds table, end to end: a shipped board having that kind is read
## from its file, an item of the kind is added with the editor's add action (a copy of one
## of the board's own, set apart), box-selected, moved, mirrored (flipped about the board's
## mirror axis), written and read back (the new item is in the file where the edits left
## it), deleted, then the edits are undone one by one, each giving back the file as it was
## before it, down to the board's own file byte for byte, but for the id counter line that
## keeps the undone add's id spent. The goal, which cannot be added or deleted, is
## box-selected, moved and mirrored.

const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const ItemKeys := preload("res://addons/board_editor/core/item_keys.gd")
const Mirror := preload("res://addons/board_editor/core/mirror.gd")
const EditCommands := preload("res://addons/board_editor/core/edit_commands.gd")
const HitTest := preload("res://addons/board_editor/core/hit_test.gd")
const AddItemsAction := preload("res://addons/board_editor/actions/add_items_action.gd")
const MoveItemsAction := preload("res://addons/board_editor/actions/move_items_action.gd")
const FlipItemsAction := preload("res://addons/board_editor/actions/flip_items_action.gd")
const DeleteItemsAction := preload("res://addons/board_editor/actions/delete_items_action.gd")

## Where the added copy goes, from the item it copies, and how far it is then moved.
const SET_APART := Vector2(7.0, 5.0)
const MOVE := Vector2(3.0, -2.0)
## Boards with kinds no shipped board has yet.
const FIXTURES := "res://tests/fixtures/boards/"


func test_every_row_goes_file_level_editor_and_back_to_the_same_file() -> void:
	for kind in ItemKinds.all():
		var path := _board_with(kind)
		assert_ne(path, "", "a shipped board or a fixture has a %s" % kind.name)
		if not path.is_empty():
			_round_trip(kind, path)


func test_the_round_trip_covers_every_row() -> void:
	var names := ItemKinds.all().map(func(kind: ItemKind) -> String: return kind.name)
	for expected in [
		"pin",
		"pocket",
		"wall",
		"hole",
		"ball_start",
		"start_pocket",
		"attacker",
		"tulip",
		"windmill",
		"goal",
		"floor_arrow",
	]:
		assert_has(names, expected)


# The first shipped board of `kind`'s game with a line of that kind (any board of its game
# for the goal, which every maze has), else the first fixture board with one (a kind no
# shipped board uses yet: the floor arrow).
func _board_with(kind: ItemKind) -> String:
	for folder in ["res://levels/%s/" % BoardLevel.kind_name(kind.game), FIXTURES]:
		var files := Array(DirAccess.get_files_at(folder))
		files.sort()
		for file: String in files:
			if not file.ends_with(".board"):
				continue
			var text := FileAccess.get_file_as_string(folder + file)
			if not kind.has_ids() or text.contains('\n{"%s": ' % kind.name):
				return folder + file
	return ""


func _round_trip(kind: ItemKind, path: String) -> void:
	var text := FileAccess.get_file_as_string(path)
	var roots: Array[String] = ["res://levels/", FIXTURES]
	var loaded := BoardLoader.load_board(path, roots)
	assert_not_null(loaded.level, "%s loads: %s" % [path, loaded.error])
	if loaded.level == null:
		return
	var level := loaded.level
	var label := "%s on %s" % [kind.name, path.get_file()]
	assert_eq(BoardTextWriter.write(level), text, label + ": the file is what the writer writes")
	var actions: Array[BoardAction] = []
	var item := _added(kind, level, actions, label)
	if item == BoardItems.NONE:
		return
	var start := BoardItems.position_of(level, item)
	var area := EditCommands.extent_of(level, item).grow(1.0)
	assert_has(HitTest.in_rect(level, area), item, label + ": a box round its area selects it")
	# What the file was before each edit: undoing that edit must give it back.
	var before: Array[String] = [text]
	if not actions.is_empty():
		before.append(BoardTextWriter.write(level))
	var move := MoveItemsAction.new(level, [item] as Array[Vector2i], MOVE)
	move.do()
	actions.append(move)
	before.append(BoardTextWriter.write(level))
	assert_eq(BoardItems.position_of(level, item), start + MOVE, label + ": moved")
	var axis := Mirror.axis_of(level)
	var flip := FlipItemsAction.new(level, [[[item] as Array[Vector2i], axis]])
	flip.do()
	actions.append(flip)
	var mirrored := Mirror.reflect(start + MOVE, axis)
	assert_almost_eq(BoardItems.position_of(level, item), mirrored, Vector2.ONE * 0.001, label)
	_check_written(kind, level, item, label)
	if kind.has_ids():
		# Deleting it takes the board back to its own items (undone below like the rest).
		before.append(BoardTextWriter.write(level))
		var had := kind.count(level)
		var delete := DeleteItemsAction.new(level, [item] as Array[Vector2i])
		delete.do()
		actions.append(delete)
		assert_eq(kind.count(level), had - 1, label + ": deleted")
	var counter := ItemIds.next_id(level, kind.list) if kind.has_ids() else 0
	for k in range(actions.size() - 1, 0, -1):
		actions[k].undo()
		assert_eq(
			BoardTextWriter.write(level),
			before[k],
			"%s: undo of %s" % [label, actions[k].get_name()]
		)
	actions[0].undo()
	var written := BoardTextWriter.write(level)
	if kind.has_ids():
		# An undone add keeps its id spent (ItemIds: an id is never handed out twice), so the
		# file gains the one line that says so, and nothing else.
		var line := '{"%s": {"%s": %d}}\n' % [BoardSchema.NEXT_IDS_FIELD, kind.list, counter]
		assert_string_contains(written, line, label + ": the spent id is kept")
		written = written.replace(line, "")
	assert_eq(written, text, label + ": undone, the file is byte for byte its own")


# Adds a copy of the board's first item of `kind` (the goal, which cannot be added, is
# returned as it is); NONE when there is nothing to copy.
func _added(
	kind: ItemKind, level: BoardLevel, actions: Array[BoardAction], label: String
) -> Vector2i:
	if not kind.has_ids():
		return BoardItems.make(kind.pick, 0)
	var source := BoardItems.NONE
	for index in kind.field_indices(level):
		if kind.is_item(level, index):
			source = BoardItems.make(kind.pick, index)
			break
	assert_ne(source, BoardItems.NONE, label + ": the board has one to copy")
	if source == BoardItems.NONE:
		return BoardItems.NONE
	var had := kind.count(level)
	var data := BoardItems.offset_set(BoardItems.extract(level, [source], Vector2.ZERO), SET_APART)
	assert_eq(BoardItems.set_size(data), 1, label + ": the item set holds the one copy")
	var add := AddItemsAction.new(level, data)
	add.do()
	actions.append(add)
	assert_eq(kind.count(level), had + 1, label + ": added")
	assert_eq(add.added.size(), 1, label + ": one new item")
	if add.added.size() != 1:
		return BoardItems.NONE
	var item: Vector2i = add.added[0]
	assert_eq(ItemKinds.of_item(level, item), kind, label + ": the new item is of its kind")
	assert_eq(
		BoardItems.position_of(level, item),
		BoardItems.position_of(level, source) + SET_APART,
		label
	)
	return item


# The edited board written and read back has the item, by its key, where the edits left it.
func _check_written(kind: ItemKind, level: BoardLevel, item: Vector2i, label: String) -> void:
	var read := BoardTextReader.read(BoardTextWriter.write(level))
	assert_true(read.has("level"), label + ": the edited file reads: " + str(read.get("error")))
	if not read.has("level"):
		return
	var again: BoardLevel = read["level"]
	var found := ItemKeys.find_all(again, [ItemKeys.of(level, item)])
	assert_eq(found.size(), 1, label + ": the written item is read back")
	if found.size() == 1:
		var at := BoardItems.position_of(again, found[0])
		assert_almost_eq(at, BoardItems.position_of(level, item), Vector2.ONE * 0.01, label)
		assert_eq(ItemKinds.of_item(again, found[0]), kind, label + ": read back as its kind")
