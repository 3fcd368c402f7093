extends GutTest
## The frozen "Loading…" ring before the first maze board: on software GL the board's first
## frame compiled every 3D shader at once and held the main thread 2 to 4 s with the ring
## standing still. MazeStepIn now brings the stage's parts on one frame at a time and the
## curtain stays up, turning, until all are shown.

const GAME := preload("res://scenes/maze/maze_game.tscn")
const CLASSIC := "res://levels/maze/classic.board"


func _game() -> MazeGame:
	var game: MazeGame = GAME.instantiate()
	add_child_autofree(game)
	return game


func _parts(game: MazeGame) -> Array[Node3D]:
	var stage := game.stage()
	var board := stage.board()
	return [board.part("walls"), board.part("frame"), stage.balls(), board.part("floor")]


func _shown(parts: Array[Node3D]) -> int:
	return parts.filter(func(part: Node3D) -> bool: return part.visible).size()


func test_the_parts_come_on_one_frame_at_a_time_then_it_says_so() -> void:
	var game := _game()
	await wait_process_frames(2)
	var stage := game.stage()
	var parts := _parts(game)
	var step_in := MazeStepIn.new()
	add_child_autofree(step_in)
	watch_signals(step_in)
	step_in.start(stage)
	assert_eq(_shown(parts), 0, "nothing of the board is drawn in the first frame")
	var counts: Array[int] = []
	for frame in parts.size():
		await get_tree().process_frame
		counts.append(_shown(parts))
	assert_eq(counts, [1, 2, 3, 4] as Array[int], "one more part each frame")
	assert_signal_not_emitted(step_in, "shown_in_full", "not before the last part is drawn")
	await wait_process_frames(3)
	assert_signal_emit_count(step_in, "shown_in_full", 1)
	assert_true(stage.table().visible, "the table too")


func test_the_table_stays_hidden_when_low_graphics_came_on_meanwhile() -> void:
	var game := _game()
	await wait_process_frames(2)
	var stage := game.stage()
	var step_in := MazeStepIn.new()
	add_child_autofree(step_in)
	step_in.start(stage)
	stage.set_look(true, stage.tutorial_look)
	await wait_process_frames(8)
	assert_false(stage.table().visible)
	assert_true(stage.board().part("floor").visible)


func test_a_held_curtain_waits_for_the_screen_then_lifts() -> void:
	var curtain := LoadingCurtain.new()
	add_child_autofree(curtain)
	var holder := Node.new()
	add_child_autofree(holder)
	var stage := Node3D.new()
	stage.add_user_signal("done")
	add_child_autofree(stage)
	curtain.cover()
	curtain.hold_until(Signal(stage, "done"), holder)
	curtain.lift()
	assert_true(curtain.is_covering(), "a lift waits while the screen draws itself")
	stage.emit_signal("done")
	assert_false(curtain.is_covering(), "and happens when it is done")
	assert_false(curtain.is_held())


func test_a_holder_leaving_ends_its_hold_and_a_new_cover_forgets_it() -> void:
	var curtain := LoadingCurtain.new()
	add_child_autofree(curtain)
	var holder := Node.new()
	add_child(holder)
	var never := Node3D.new()
	never.add_user_signal("done")
	add_child_autofree(never)
	curtain.cover()
	curtain.hold_until(Signal(never, "done"), holder)
	curtain.lift()
	remove_child(holder)
	holder.free()
	assert_false(curtain.is_covering(), "a screen freed early does not leave it up")
	var other := Node.new()
	add_child_autofree(other)
	curtain.hold_until(Signal(never, "done"), other)
	curtain.cover()
	assert_false(curtain.is_held(), "a new screen on its way forgets the old hold")
	curtain.lift()
	assert_false(curtain.is_covering())
