extends GutTest
## The goal reads: the panel says "In goal 1 / 4" in the same frame the rules count a ball
## in (its drawn disc over the goal's rim), the goal's dish lights up then, and the dish
## the floor draws has exactly the rule's centre and radius as its edge.

const GAME := preload("res://scenes/maze/maze_game.tscn")
const TEST_SETTINGS := "user://test_maze_goal_settings.cfg"
const TEST_SAVE := "user://test_maze_goal_save.cfg"
## A board whose goal room leaves the goal's edge clear of walls every way.
const BOARD := "res://levels/maze/garden.board"

var _game: MazeGame


func before_all() -> void:
	App.load_player_files(TEST_SETTINGS, TEST_SAVE)
	App.request_board(BoardLevel.MAZE_NAME, BOARD)


func after_all() -> void:
	App.request_board(BoardLevel.MAZE_NAME, "res://levels/maze/classic.board")
	App.load_player_files(App.SETTINGS_PATH, App.SAVE_PATH)
	for path in [TEST_SETTINGS, TEST_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


func before_each() -> void:
	_game = GAME.instantiate()
	add_child_autofree(_game)


# Puts the first ball `from_centre` px from the goal's centre (down and right, clear of the
# room's walls), at rest, and runs one frame of play.
func _ball_at(from_centre: float) -> void:
	var rules: MazeRules = _game.rules
	var id := rules.world.get_ids()[0]
	var at := rules.level.goal_center + Vector2.ONE.normalized() * from_centre
	rules.world.set_ball_position(id, at)
	rules.world.set_ball_velocity(id, Vector2.ZERO)
	rules.advance(1.0 / 60.0)


func test_the_panel_counts_a_ball_the_moment_the_rule_does() -> void:
	var rules: MazeRules = _game.rules
	var total := rules.ball_total()
	assert_eq(_game.goal_count_text(), "In goal  0 / %d" % total)
	rules.start()
	var reach := rules.level.goal_radius + rules.level.ball_radius
	_ball_at(reach + 1.0)
	assert_eq(rules.count_in_goal(), 0, "disc just clear of the edge: not in")
	assert_eq(_game.goal_count_text(), "In goal  0 / %d" % total)
	assert_eq(_stage().goal_glow(), 0.0, "no light yet")
	_ball_at(reach - 1.0)
	assert_eq(rules.count_in_goal(), 1, "disc just over the edge: in")
	assert_eq(_game.goal_count_text(), "In goal  1 / %d" % total, "said in the same frame")
	assert_gt(_stage().goal_glow(), 0.9, "the goal lights up")
	_stage().sync_balls(rules, 1.0)
	assert_eq(_stage().goal_glow(), 0.0, "and fades within a second")
	rules.reset()
	assert_eq(_game.goal_count_text(), "In goal  0 / %d" % total, "a reset clears it")


func test_the_dish_edge_is_the_rule_edge() -> void:
	var level: BoardLevel = _game.rules.level
	var floor_material: ShaderMaterial = _stage().board().part("floor").material_override
	assert_eq(floor_material.get_shader_parameter("goal_center"), level.goal_center)
	assert_eq(floor_material.get_shader_parameter("goal_radius"), level.goal_radius)


func _stage() -> MazeStage:
	return _game.get_node("Stage")
