extends GutTest
## No wall after Cloister (trial 8: Garden Path took 3:27 against a 0:14 gold, and its fourth
## ball most of that: one ball had to stop part-way twice, in a row of three cells and again
## in a column of four). Garden Path now gives that ball a rest at each stop (a wall ends the
## row at the column it must take, and the column at the room's side door), so the board is
## won with whole tilts held in turn, as Cloister is.

const FRAME := 1.0 / 60.0
const HOLD_SECONDS := 2.2
const BOARD := "res://levels/maze/garden.board"


func test_garden_path_is_won_with_whole_tilts_only() -> void:
	var keys: Array[Vector2] = [
		Vector2.RIGHT,
		Vector2.DOWN,
		Vector2.UP,
		Vector2.LEFT,
		Vector2.DOWN,
		Vector2.RIGHT,
		Vector2.DOWN,
		Vector2.LEFT,
		Vector2.RIGHT,
		Vector2.UP,
		Vector2.LEFT,
	]
	var rules := MazeRules.new(BoardLoader.load_board(BOARD).level)
	var mixer := TiltMixer.new()
	rules.start()
	for key in keys:
		for frame in int(HOLD_SECONDS / FRAME):
			rules.set_tilt(mixer.update(FRAME, key, Vector3.ZERO))
			rules.advance(FRAME)
		if rules.is_over():
			break
	gut.p(
		(
			"Garden Path, whole tilts: won %s in %.1f s"
			% [rules.state == MazeRules.State.WON, rules.elapsed]
		)
	)
	assert_eq(rules.state, MazeRules.State.WON, "%d in the goal" % rules.count_in_goal())
