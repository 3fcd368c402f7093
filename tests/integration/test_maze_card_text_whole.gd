extends GutTest
## Trial 9, bug 3: the selected maze card's description read "of turns that double back,
## with... stops part-way.": it had been reading through line by line, and the label's "…"
## stayed on the line where the resting text was cut, now in the middle. Every shipped maze
## card now shows its whole description at 1280 × 720 (no reading through), and a text too
## long for any card reads through with no "…" inside it, after a rest on its first lines.

const MazeLevelSelectWindow := preload("res://tests/integration/maze_level_select_window.gd")
const ScratchSave := preload("res://tests/helpers/scratch_save.gd")
const EMPTY_USER_ROOT := "user://test_maze_card_text_whole_no_boards"
const SAVE := "user://test_maze_card_text_whole_save.cfg"

var _real_save: RefCounted = null


func before_each() -> void:
	_real_save = ScratchSave.swap_in(SAVE)
	App.settings.unlock_all_boards = true  # every card open, as after some play


func after_each() -> void:
	ScratchSave.restore(_real_save, SAVE)
	App.level_select_kind = BoardLevel.PACHINKO_NAME


func test_every_shipped_maze_card_shows_its_whole_description() -> void:
	var screen := await MazeLevelSelectWindow.open(self, Vector2i(1280, 720), EMPTY_USER_ROOT)
	var checked := 0
	for button in screen.cards():
		var card := button as LevelCard
		if card.long_text() == null or card.medal_badges() == null:
			continue
		checked += 1
		card.grab_focus()
		await wait_physics_frames(2)
		var text := card.long_text()
		assert_true(
			text.shows_whole_text(), "%s: %d lines, all shown" % [card.name, text.wrapped_lines()]
		)
		assert_false(text.reads_through(), "%s: nothing to read through" % card.name)
	assert_gte(checked, 14, "every shipped maze board")


func test_a_text_reading_through_has_no_cut_mark_inside_it() -> void:
	var label := Label.new()
	label.autowrap_mode = TextServer.AUTOWRAP_WORD_SMART
	label.size = Vector2(120, 40)
	label.text = "one two three four five six seven eight nine ten eleven twelve thirteen"
	var thumb := Control.new()
	add_child_autofree(label)
	add_child_autofree(thumb)
	var text := CardLongText.new(label, thumb, 60.0, 1)
	text.set_focused(true)
	text.fit()
	assert_true(text.reads_through())
	text.advance(CardLongText.START_REST_SECONDS - 0.1)
	assert_eq(label.lines_skipped, 0, "it rests on its first line a while")
	for i in 10:
		text.advance(CardLongText.READ_SECONDS)
		if label.lines_skipped > 0:
			break
	assert_gt(label.lines_skipped, 0, "then it moves on")
	assert_eq(label.text_overrun_behavior, TextServer.OVERRUN_NO_TRIMMING, 'no "…" past the top')
