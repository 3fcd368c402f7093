extends GutTest
## The shipped boards: they load, validate clean, match their recipes and survive a save and
## load unchanged.

const SHIPPED := ["res://levels/pachinko/classic.board", "res://levels/maze/classic.board"]
const TEMP := "user://test_board_roundtrip.board"


func after_all() -> void:
	DirAccess.remove_absolute(ProjectSettings.globalize_path(TEMP))


func test_every_shipped_board_loads_without_issues() -> void:
	for kind: int in [BoardLevel.Kind.PACHINKO, BoardLevel.Kind.MAZE]:
		var results := BoardLoader.list_boards(kind)
		assert_gt(results.size(), 0, "boards of kind %d" % kind)
		for loaded in results:
			assert_true(loaded.ok(), loaded.error)
			if loaded.ok():
				assert_eq(loaded.level.kind, kind, loaded.path)
				assert_eq(BoardValidator.validate(loaded.level).size(), 0, loaded.path)


func test_every_shipped_board_has_a_level_scene() -> void:
	for kind: int in [BoardLevel.Kind.PACHINKO, BoardLevel.Kind.MAZE]:
		for loaded in BoardLoader.list_boards(kind):
			var scene_path := (
				"res://scenes/boards/%s_%s.tscn"
				% [BoardLevel.kind_name(kind), loaded.path.get_file().get_basename()]
			)
			assert_true(
				FileAccess.file_exists(scene_path),
				"%s (tools/make_board_scenes.gd writes it)" % scene_path
			)
			if not FileAccess.file_exists(scene_path):
				continue
			var scene: PackedScene = load(scene_path)
			var node := scene.instantiate()
			assert_true(node is BoardNode, scene_path)
			if node is BoardNode:
				var board := node as BoardNode
				assert_eq(board.level.resource_path, loaded.path, "the scene edits the file itself")
			node.free()


func test_shipped_board_ids_are_unique() -> void:
	var seen := {}
	for kind: int in [BoardLevel.Kind.PACHINKO, BoardLevel.Kind.MAZE]:
		for loaded in BoardLoader.list_boards(kind):
			if loaded.ok():
				assert_false(
					seen.has(loaded.level.board_id), "duplicate id " + loaded.level.board_id
				)
				seen[loaded.level.board_id] = true


func test_classic_pachinko_matches_the_chapter() -> void:
	var level := _load(SHIPPED[0])
	assert_eq(level.pockets.size(), 5)
	# The chapter paid 4 a pocket, this board 6 until a held handle strength that fed the
	# middle paid 1.6 balls a ball: the side pair, which every strength reaches least, pay
	# most now (rules 5, tools/power_returns.gd).
	var payouts: Array[int] = []
	for spec in level.pockets:
		payouts.append(spec.payout)
	assert_eq(payouts, [3, 10, 10, 2, 2] as Array[int], "top 3, the sides 10, the low pair 2")
	assert_eq(level.cup_start_balls, 25)
	assert_eq(level.ball_radius, 5.0)
	assert_between(level.pins.size(), 200, 900, "a few hundred pins")
	assert_lte(level.size.x, 720.0)
	assert_lte(level.size.y, 720.0)
	var specials := 0
	for flag in level.pin_special:
		specials += flag
	assert_eq(specials, 5, "one special pin per pocket")
	assert_between(level.gutter_start_deg, 0.0, 90.0, "gutter at the bottom")
	assert_between(level.gutter_end_deg, 90.0, 180.0, "gutter at the bottom")
	# The rail opens on the upper right (-30 degrees since the aimed launch), so a weak shot
	# drops in near the rail and a strong one rides the ring over the top.
	var entry := LaunchRail.entry_point(level)
	assert_lt(entry.y, level.ring_center.y - level.ring_radius * 0.4, "the rail opens up high")
	assert_gt(entry.x, level.ring_center.x + level.ring_radius * 0.6, "on the right")


func test_classic_maze_is_the_tutorial_layout() -> void:
	var level := _load(SHIPPED[1])
	assert_eq([level.grid_cols, level.grid_rows], [10, 9])
	assert_eq([level.path_width, level.wall_width], [25.0, 10.0])
	assert_eq(level.size, Vector2(350, 315))
	assert_eq(level.walls.size(), 47 * 2, "the tutorial's 47 walls")
	# First border wall, (0, 0) horizontal length 10, and the last, (9, 5) vertical length 2.
	assert_eq(level.walls[0], Vector2(0, 0))
	assert_eq(level.walls[1], Vector2(350, 0))
	assert_eq(level.walls[92], Vector2(315, 175))
	assert_eq(level.walls[93], Vector2(315, 245))
	var starts := PackedVector2Array(
		[Vector2(17.5, 17.5), Vector2(332.5, 17.5), Vector2(17.5, 297.5), Vector2(332.5, 297.5)]
	)
	assert_eq(level.ball_starts, starts)
	assert_eq(level.goal_center, Vector2(175, 157.5))
	# the tutorial drew a 32.5 px ring; its dish ran under the goal room's walls (24 clears them)
	assert_eq(level.goal_radius, 24.0)
	assert_eq(level.holes.size(), 8)
	assert_eq(level.holes[0], Vector2(17.5, 192.5), "hole (0, 5)")
	assert_eq(level.hole_radius, 9.0)


func test_shipped_boards_round_trip_unchanged() -> void:
	for path: String in SHIPPED:
		var level := _load(path)
		assert_eq(ResourceSaver.save(level, TEMP), OK)
		var again: BoardLevel = ResourceLoader.load(TEMP, "", ResourceLoader.CACHE_MODE_IGNORE)
		assert_not_null(again, path)
		if again != null:
			_assert_same(level, again, path)


func _assert_same(a: Resource, b: Resource, label: String) -> void:
	for property in a.get_property_list():
		if not property["usage"] & PROPERTY_USAGE_STORAGE:
			continue
		var name: String = property["name"]
		if name in ["resource_path", "script", "resource_name"]:
			continue
		var va: Variant = a.get(name)
		var vb: Variant = b.get(name)
		if va is Resource and vb is Resource:
			var ra: Resource = va
			var rb: Resource = vb
			_assert_same(ra, rb, "%s.%s" % [label, name])
		elif va is Array and vb is Array:
			var left: Array = va
			var right: Array = vb
			assert_eq(left.size(), right.size(), "%s.%s size" % [label, name])
			for i in mini(left.size(), right.size()):
				var a_item: Resource = left[i]
				var b_item: Resource = right[i]
				_assert_same(a_item, b_item, "%s.%s[%d]" % [label, name, i])
		else:
			# Text form: exact, and compares the type too.
			assert_eq(var_to_str(vb), var_to_str(va), "%s.%s" % [label, name])


func _load(path: String) -> BoardLevel:
	var loaded := BoardLoader.load_board(path)
	assert_true(loaded.ok(), loaded.error)
	return loaded.level
