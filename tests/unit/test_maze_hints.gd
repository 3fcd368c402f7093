extends GutTest
## The maze's start hints say what the board really is: hard mode on a board without black
## holes says it plays as easy (a play trial pressed H on First Roll, read "avoid the black
## holes" and found none).


func test_hard_mode_with_holes_says_avoid_them() -> void:
	assert_string_contains(MazeHints.start(true, 4, 8), "avoid the black holes")


func test_hard_mode_on_a_board_without_holes_says_it_plays_as_easy() -> void:
	var hint := MazeHints.start(true, 1, 0)
	assert_string_contains(hint, "no black holes")
	assert_false(hint.contains("avoid the black holes"))


func test_a_board_without_holes_never_asks_for_hard_mode() -> void:
	assert_false(MazeHints.start(false, 2, 0).contains("hard mode"), "the start hint")
	assert_eq(MazeHints.won(false, 0), "", "the win hint")
	assert_string_contains(MazeHints.start(false, 4, 8), "hard mode")
	assert_string_contains(MazeHints.won(false, 8), "hard mode")
	assert_string_contains(MazeHints.start(false, 1, 0), "rolls downhill")


func test_boards_two_to_five_say_what_to_try_in_easy_mode() -> void:
	for board_id in MazeProgress.ORDER.slice(1, 5):
		var hint := MazeHints.start(false, 4, 2, board_id)
		assert_string_contains(hint, "Tip: ", "%s has a tip" % board_id)
		assert_lt(MazeHints.TIPS[board_id].length(), 80, "%s: a short line" % board_id)
		assert_false(MazeHints.start(true, 4, 2, board_id).contains("Tip: "), "easy mode only")
	assert_false(MazeHints.start(false, 4, 2, "maze_tower").contains("Tip: "), "later boards: none")


# Trial 7: Garden Path, billed as the board to learn the tilt, needed a ball stopped part-way
# along a corridor with a brief tilt, and nothing said so. Trial 8: Garden Path no longer
# needs it (test_maze_garden_full_tilts.gd); Switchbacks, the first board that does, teaches it.
func test_switchbacks_teaches_the_small_tilt() -> void:
	var hint := MazeHints.start(false, 4, 2, "maze_switchbacks")
	assert_string_contains(hint, "tap a key, or hold Shift")
	assert_string_contains(hint, "part-way")


# Trial 8 asked for a finer tilt: the controls line names the key that halves it.
func test_the_controls_line_names_the_fine_tilt_key() -> void:
	assert_string_contains(MazeHints.controls(), "Shift\u00a0fine\u00a0tilt")


# Trial 9: a tap is a fixed nudge, a hold rolls on, and a drag on the board tilts it: the
# controls line says all three.
func test_the_controls_line_says_tap_hold_and_drag() -> void:
	var line := MazeHints.controls().split("\n")[0]
	assert_string_contains(line, "Tap a key to nudge")
	assert_string_contains(line, "hold to roll")
	assert_string_contains(line, "drag the board")
