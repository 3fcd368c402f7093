extends GutTest
## The ItemKinds table: every row names fields BoardLevel has, each list, file key and id
## field once, and the table agrees with what it replaced (the id lists' order, which the
## board file's counters line is written in, and the editor's picks).

const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const Layers := preload("res://addons/board_editor/core/layers.gd")


func test_every_row_names_fields_that_board_level_has() -> void:
	var level := BoardLevel.new()
	var known := {}
	for property in level.get_property_list():
		known[property["name"]] = true
	for kind in ItemKinds.all():
		assert_true(known.has(kind.field), "%s: field %s" % [kind.name, kind.field])
		if kind.has_ids():
			assert_true(known.has(kind.id_field), "%s: id field %s" % [kind.name, kind.id_field])
			assert_eq(typeof(level.get(kind.id_field)), TYPE_PACKED_INT32_ARRAY, kind.id_field)
		for field in kind.item_fields + kind.position_fields:
			assert_true(known.has(field), "%s: field %s" % [kind.name, field])
		assert_false(kind.singular.is_empty(), kind.name + " has a name")
		assert_false(kind.plural.is_empty(), kind.name + " has a plural")


func test_lists_file_keys_and_id_fields_are_each_used_once() -> void:
	var lists := {}
	var keys := {}
	var ids := {}
	for kind in ItemKinds.all():
		assert_false(lists.has(kind.list), "list %s once" % kind.list)
		assert_false(keys.has(kind.name), "file key %s once" % kind.name)
		lists[kind.list] = true
		keys[kind.name] = true
		if kind.has_ids():
			assert_false(ids.has(kind.id_field), "id field %s once" % kind.id_field)
			ids[kind.id_field] = true
		assert_eq(ItemKinds.of_list(kind.list), kind)
		assert_eq(ItemKinds.of_name(kind.name), kind)


func test_the_shapes_match_the_fields_they_read() -> void:
	var level := BoardLevel.new()
	for kind in ItemKinds.all():
		var value: Variant = level.get(kind.field)
		match kind.shape:
			ItemKind.Shape.POINT, ItemKind.Shape.SEGMENT:
				assert_eq(typeof(value), TYPE_PACKED_VECTOR2_ARRAY, kind.name)
			ItemKind.Shape.SPEC, ItemKind.Shape.ROLE_SPEC:
				assert_eq(typeof(value), TYPE_ARRAY, kind.name)
				assert_false(kind.spec_values.is_empty(), kind.name + " keeps its values")
				assert_eq(kind.spec_values[0], "position", kind.name)
			ItemKind.Shape.SINGLE:
				assert_eq(typeof(value), TYPE_VECTOR2, kind.name)
		assert_true(kind.position_fields.has(kind.field), kind.name + " moves its own field")


func test_every_editor_pick_has_a_row() -> void:
	for pick: int in BoardItems.Kind.values():
		assert_not_null(ItemKinds.of_pick(pick), "pick %s" % BoardItems.Kind.keys()[pick])
	for role: int in BonusPocketSpec.Role.values():
		var kind := ItemKinds.of_role(role)
		assert_eq(kind.name, BonusPocketSpec.ROLE_KEYS[role])
		assert_eq(kind.pick, BoardItems.Kind.BONUS)


func test_every_row_is_on_an_editor_layer_the_board_painter_draws() -> void:
	for kind in ItemKinds.all():
		assert_false(kind.layer.is_empty(), kind.name + " is on a layer")
		assert_true(
			BoardPainter.Layer.has(kind.paint_layer), "%s: %s" % [kind.name, kind.paint_layer]
		)
		assert_has(Layers.for_kind(kind.game), kind.layer, kind.name)
		assert_eq(Layers.of_item(Vector2i(kind.pick, 0)), kind.layer, kind.name)
		var flag: int = BoardPainter.Layer[kind.paint_layer]
		assert_eq(Layers.painter_mask([kind.layer] as Array[String]), flag, kind.name)


func test_a_copied_board_shares_no_item_resource_and_watches_every_one() -> void:
	var level := BoardLevel.new()
	level.pockets = [PocketSpec.create(Vector2(10, 10), 20, 20, 3)] as Array[PocketSpec]
	level.bonus_pockets = (
		[BonusPocketSpec.of_role(BonusPocketSpec.Role.TULIP, Vector2(50, 50), 26, 26, 3)]
		as Array[BonusPocketSpec]
	)
	level.windmills = [WindmillSpec.driven(Vector2(90, 90), 4, 20, 100)] as Array[WindmillSpec]
	level.floor_arrows = [FloorArrowSpec.create(Vector2(20, 60), 45.0)] as Array[FloorArrowSpec]
	var copy := level.duplicate_level()
	for kind in ItemKinds.all():
		if kind.shape != ItemKind.Shape.SPEC and kind.shape != ItemKind.Shape.ROLE_SPEC:
			continue
		var mine: Array = level.get(kind.field)
		var theirs: Array = copy.get(kind.field)
		assert_eq(theirs.size(), mine.size(), kind.field)
		assert_ne(theirs[0], mine[0], kind.field + ": copied, not shared")
		assert_eq(theirs.get_typed_class_name(), mine.get_typed_class_name(), kind.field)
		watch_signals(level)
		var spec: Resource = mine[0]
		spec.set("position", Vector2(1, 1))
		assert_signal_emitted(level, "changed", kind.field + ": an edit of one is the board's")
