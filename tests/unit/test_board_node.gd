extends GutTest
## BoardNode follows its level: redraws on change, lists validator findings as warnings.


func test_warnings_follow_the_level() -> void:
	var node: BoardNode = add_child_autofree(BoardNode.new())
	assert_eq(node._get_configuration_warnings().size(), 1, "asks for a level")
	var level: BoardLevel = _tiny("maze")
	node.level = level
	assert_eq(node._get_configuration_warnings().size(), 0)
	level.goal_radius = 1.0  # setter emits changed
	var warnings: PackedStringArray = node._get_configuration_warnings()
	assert_eq(warnings.size(), 2)
	assert_string_contains(warnings[0], "goal")
	assert_string_contains(warnings[1], "was not checked", "and why reachability was skipped")


func test_in_place_edits_need_notify_edited() -> void:
	var node: BoardNode = add_child_autofree(BoardNode.new())
	var level: BoardLevel = _tiny("maze")
	node.level = level
	assert_eq(node.issues().size(), 0)
	level.walls.append(Vector2(1, 1))  # an in-place edit: no setter runs
	level.notify_edited()
	var kinds := node.issues().map(func(issue: BoardIssue) -> String: return issue.kind)
	assert_eq(kinds, ["odd_wall_points", "reachability_skipped"])


func test_swapping_levels_disconnects_the_old_one() -> void:
	var node: BoardNode = add_child_autofree(BoardNode.new())
	var first: BoardLevel = _tiny("maze")
	var second: BoardLevel = _tiny("pachinko")
	node.level = first
	node.level = second
	assert_false(first.changed.is_connected(node._on_level_changed))
	assert_true(second.changed.is_connected(node._on_level_changed))


func test_fit_transform_centres_the_board_and_its_overhang() -> void:
	var level: BoardLevel = load("res://levels/maze/classic.board")
	# The maze's edge walls reach 5 px outside its 350 × 315 area: 360 × 325 in all.
	var xform := BoardPainter.fit_transform(level, Rect2(0, 0, 720, 720))
	assert_almost_eq(xform.get_scale(), Vector2(2, 2), Vector2.ONE * 1e-5)
	assert_almost_eq(xform * Vector2(-5, -5), Vector2(0, 35), Vector2.ONE * 1e-4)
	assert_almost_eq(xform * (level.size + Vector2(5, 5)), Vector2(720, 685), Vector2.ONE * 1e-4)


func _tiny(kind: String) -> BoardLevel:
	var path := "res://tests/fixtures/boards/tiny_%s.tres" % kind
	return (load(path) as BoardLevel).duplicate_level()


func test_editing_a_pocket_on_its_own_updates_the_board() -> void:
	var node: BoardNode = add_child_autofree(BoardNode.new())
	var level := _tiny("pachinko")
	node.level = level
	assert_eq(node.issues().size(), 0)
	level.pockets[0].width = 4.0  # mouth too narrow for a ball
	assert_gt(node.issues().size(), 0, "the node heard the pocket change")
