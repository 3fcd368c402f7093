extends GutTest
## The maze camera is fixed and always shows the whole board, frame included: every shipped
## board at 1280 × 720, 900 × 700 and 720 × 1280, at rest and at full tilt every way, lies
## inside the region the side panel leaves (measured through the real Camera3D), and at
## 1280 × 720 a ball is drawn at least 14 px across anywhere on the board at any tilt.
## A board that cannot keep its balls that big is made with fewer, wider corridors.

const GAME := preload("res://scenes/maze/maze_game.tscn")
const SIZES: Array[Vector2i] = [Vector2i(1280, 720), Vector2i(900, 700), Vector2i(720, 1280)]
const MIN_BALL_PX := 14.0
const FULL := 12.0
const TILTS: Array[Vector2] = [
	Vector2.ZERO,
	Vector2(FULL, FULL),
	Vector2(-FULL, FULL),
	Vector2(FULL, -FULL),
	Vector2(-FULL, -FULL),
	Vector2(FULL, 0),
	Vector2(-FULL, 0),
	Vector2(0, FULL),
	Vector2(0, -FULL),
]


## The game screen in a `view`-sized window, laid out; returns [game, board region].
func _game(view: Vector2i) -> Array:
	var port := SubViewport.new()
	port.size = view
	port.render_target_update_mode = SubViewport.UPDATE_DISABLED
	add_child_autofree(port)
	var game: MazeGame = GAME.instantiate()
	port.add_child(game)
	await wait_process_frames(2)
	var region: Rect2 = game.lay_out()
	await wait_process_frames(1)
	return [game, region]


## The shipped maze boards, by file name.
static func shipped_boards() -> Array[String]:
	var out: Array[String] = []
	for file in DirAccess.get_files_at("res://levels/maze"):
		if file.ends_with(".board"):
			out.append(file.get_basename())
	out.sort()
	return out


## The screen points of the board's outer box corners (frame included) through the camera.
func _corners_on_screen(stage: MazeStage) -> PackedVector2Array:
	var pivot: Node3D = stage.board().get_parent()
	var box := stage.board().outer_box()
	var out := PackedVector2Array()
	for i in 8:
		out.append(stage.camera().unproject_position(pivot.global_transform * box.get_endpoint(i)))
	return out


## The smallest a ball is drawn (px across) at the board's four inner corners as tilted now.
static func smallest_ball_px(stage: MazeStage, level: BoardLevel) -> float:
	var pivot: Node3D = stage.board().get_parent()
	var camera := stage.camera()
	var r := level.ball_radius
	var smallest := INF
	for at: Vector2 in [
		Vector2(r, r),
		Vector2(level.size.x - r, r),
		Vector2(r, level.size.y - r),
		level.size - Vector2(r, r)
	]:
		var centre := pivot.global_transform * MazeMeshes.to_local(level.size, at, r)
		var side := camera.global_basis.x * r * MazeMeshes.UNITS_PER_PX
		var across := camera.unproject_position(centre + side).distance_to(
			camera.unproject_position(centre - side)
		)
		smallest = minf(smallest, across)
	return smallest


func test_every_shipped_board_is_whole_in_view_at_every_size_and_tilt() -> void:
	var boards := shipped_boards()
	assert_gt(boards.size(), 0)
	var report: Array[String] = []
	for view in SIZES:
		var made: Array = await _game(view)
		var game: MazeGame = made[0]
		var region: Rect2 = made[1]
		var side: Control = game.get_node("Side")
		assert_false(side.get_global_rect().intersects(region), "%s: the panel beside" % view)
		var stage := game.stage()
		for board in boards:
			var level := BoardLoader.load_board("res://levels/maze/%s.board" % board).level
			stage.set_level(level, false)
			var smallest := INF
			for tilt in TILTS:
				stage.set_tilt(tilt)
				for p in _corners_on_screen(stage):
					assert_true(
						region.grow(0.5).has_point(p),
						(
							"%s at %s tilted %s: frame corner %s outside %s"
							% [board, view, tilt, p, region]
						)
					)
				smallest = minf(smallest, smallest_ball_px(stage, level))
			stage.set_tilt(Vector2.ZERO)
			if view == Vector2i(1280, 720):
				report.append("%s %.1f" % [board, smallest])
				assert_gte(
					smallest, MIN_BALL_PX, "%s at 1280x720: a ball is %.1f px" % [board, smallest]
				)
	gut.p("smallest ball px at 1280x720 (any corner, any tilt): " + ", ".join(report))


func test_the_camera_does_not_move_while_the_balls_roll() -> void:
	var made: Array = await _game(Vector2i(1280, 720))
	var game: MazeGame = made[0]
	var stage := game.stage()
	var level := BoardLoader.load_board("res://levels/maze/the_deep.board").level
	stage.set_level(level, false)
	var rules := MazeRules.new(level)
	var before := [
		stage.camera().global_transform, stage.camera().frustum_offset, stage.camera().size
	]
	rules.world.set_ball_position(rules.world.get_ids()[0], level.goal_center)
	for frame in 5:
		stage.sync_balls(rules, 1.0 / 60.0)
	var after := [
		stage.camera().global_transform, stage.camera().frustum_offset, stage.camera().size
	]
	assert_eq(after, before)


func test_the_game_puts_its_panel_beside_the_board_or_under_it_in_portrait() -> void:
	for view in SIZES:
		var made: Array = await _game(view)
		var game: MazeGame = made[0]
		var region: Rect2 = made[1]
		var side_rect := (game.get_node("Side") as Control).get_global_rect()
		assert_false(side_rect.intersects(region), "%s: the text keeps off the board" % view)
		assert_true(
			Rect2(Vector2.ZERO, Vector2(view)).encloses(side_rect.grow(-1.0)),
			"%s: on screen %s" % [view, side_rect]
		)
		if view.y > view.x:
			assert_gt(side_rect.position.y, region.end.y - 1.0, "portrait: the panel is below")
