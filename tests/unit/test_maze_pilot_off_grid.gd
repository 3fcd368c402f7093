extends GutTest
## The maze pilot on a board with a wall off the grid's lines. QA moved one end of a
## Courtyards wall by one cell (the wall along y = 70 now slants from (70, 105) to
## (140, 70) on the 10 x 10 Courtyards; to (175, 70) on the 12 x 12 one it was found on):
## a person still wins it, but the pilot's grid lost the whole board over that one wall
## ("not a grid"), fell back to steering the ball nearest the goal and never got more than
## one ball in. The grid now draws an off-grid wall onto its cell sides (those
## between the cells whose centres it separates), and the planner plays on.

const COURTYARDS := "res://levels/maze/courtyards.board"
const MOVED_FROM := Vector2(70, 70)
const MOVED_TO := Vector2(70, 105)


# Courtyards with the end of the wall at MOVED_FROM (the one along y = 70) moved to MOVED_TO.
func _edited_courtyards() -> BoardLevel:
	var level := BoardLoader.load_board(COURTYARDS).level
	var walls := level.walls.duplicate()
	for i in walls.size():
		var other := walls[i ^ 1]
		if walls[i] == MOVED_FROM and other.y == MOVED_FROM.y and other.x > MOVED_FROM.x:
			walls[i] = MOVED_TO
			level.walls = walls
			return level
	return null


func test_the_edit_is_a_board_a_person_can_still_win() -> void:
	var level := _edited_courtyards()
	assert_not_null(level, "the wall along y = 70 from (70, 70) is on the board")
	assert_eq(BoardValidator.errors(level), [] as Array[BoardIssue], "it is a valid board")
	var flood := MazeFlood.new(level, false)
	for start in level.ball_starts:
		assert_true(flood.reaches_goal(start), "every start still reaches the goal")


func test_an_off_grid_wall_closes_the_sides_it_separates() -> void:
	var grid := MazeGrid.new(_edited_courtyards())
	assert_true(grid.is_grid, "one slanted wall keeps the grid")
	assert_eq(grid.off_grid_walls, 1)
	# it crosses the line between the centres of cells (2, 2) and (2, 3) at y = 96: closed
	assert_false(grid.is_open(2, 2, 0, 1), "the slant parts (2, 2) from (2, 3) below it")
	# the sides it left along y = 70 are open now, past its upper end still closed
	assert_true(grid.is_open(2, 1, 0, 1), "(2, 1) opens down into (2, 2)")
	assert_false(grid.is_open(3, 1, 0, 1), "the slant still parts (3, 1) from (3, 2)")


func test_the_shipped_mazes_lie_on_their_grids() -> void:
	# their pilot plays exactly as before: every wall on the grid's lines
	for loaded in BoardLoader.list_boards(BoardLevel.Kind.MAZE):
		var grid := MazeGrid.new(loaded.level)
		assert_eq(grid.off_grid_walls, 0, loaded.path)


func test_the_pilot_wins_courtyards_after_the_edit() -> void:
	var level := _edited_courtyards()
	var easy := MazeAutoplay.run(level, 120.0, 1, false)
	assert_true(easy["won"], "easy seed 1: %s balls in the goal at the end" % easy["balls_in_goal"])
	var hard := MazeAutoplay.run(level, 120.0, 1, true)
	assert_true(hard["won"], "hard seed 1: %s balls in the goal" % hard["balls_in_goal"])
	assert_eq(hard["balls_lost_in_holes"], 0, "and none lost")
