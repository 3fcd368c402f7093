extends GutTest
## The first board is one anyone can finish: a player who holds the arrow keys in the order
## the board shows (right, down, left, down, right; 2.5 s each, as the keys ramp the
## tilt through TiltMixer) wins First Roll, and so does the same with Two Together's two
## balls and one more fold.

const FRAME := 1.0 / 60.0
const HOLD_SECONDS := 2.5


# Plays `board` holding each key of `keys` (unit vectors, x right, y down) in turn for
# HOLD_SECONDS at 60 frames a second; returns the rules when done.
func _play(board: String, keys: Array[Vector2]) -> MazeRules:
	var rules := MazeRules.new(BoardLoader.load_board("res://levels/maze/%s.board" % board).level)
	var mixer := TiltMixer.new()
	rules.start()
	for key in keys:
		for frame in int(HOLD_SECONDS / FRAME):
			rules.set_tilt(mixer.update(FRAME, key, Vector3.ZERO))
			rules.advance(FRAME)
			if rules.is_over():
				return rules
	return rules


func test_holding_the_keys_in_turn_wins_first_roll() -> void:
	var keys: Array[Vector2] = [
		Vector2.RIGHT, Vector2.DOWN, Vector2.LEFT, Vector2.DOWN, Vector2.RIGHT
	]
	var rules := _play("first_roll", keys)
	gut.p("First Roll: won %s in %.1f s" % [rules.state == MazeRules.State.WON, rules.elapsed])
	assert_eq(rules.state, MazeRules.State.WON, "%d in the goal" % rules.count_in_goal())
	assert_lt(rules.elapsed, 5 * HOLD_SECONDS, "won in %.1f s" % rules.elapsed)


func test_holding_the_keys_in_turn_wins_two_together() -> void:
	var keys: Array[Vector2] = [
		Vector2.RIGHT,
		Vector2.DOWN,
		Vector2.LEFT,
		Vector2.DOWN,
		Vector2.RIGHT,
		Vector2.DOWN,
		Vector2.LEFT
	]
	var rules := _play("two_together", keys)
	gut.p("Two Together: won %s in %.1f s" % [rules.state == MazeRules.State.WON, rules.elapsed])
	assert_eq(rules.state, MazeRules.State.WON, "%d in the goal" % rules.count_in_goal())
	assert_lt(rules.elapsed, 7 * HOLD_SECONDS, "won in %.1f s" % rules.elapsed)
