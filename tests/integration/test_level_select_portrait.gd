extends GutTest
## The level select on a portrait phone: the project draws its 1280 × 720 design at 0.56 on a
## 720 × 1280 screen, which made the cards' text 7-11 px in three narrow columns. Now the
## screen's content is drawn 1.3 times bigger in a portrait window and reflows to two
## columns: a card's description is at least 14 px on the screen, the whole screen stays in
## the window, and the header's title wraps instead of being cut ("Tilt M…"). A landscape
## window is laid out as before.

const MazeLevelSelectWindow := preload("res://tests/integration/maze_level_select_window.gd")
const EMPTY_USER_ROOT := "user://test_level_select_portrait_no_boards"


func before_each() -> void:
	App.settings.unlock_all_boards = true


func after_each() -> void:
	App.settings.unlock_all_boards = false
	App.level_select_kind = BoardLevel.PACHINKO_NAME


## The maze level select in a window of `size` pixels, stretched as the project stretches.
func _open_in_window(size: Vector2i) -> LevelSelect:
	return await MazeLevelSelectWindow.open(self, size, EMPTY_USER_ROOT)


func test_portrait_cards_read_at_14_px_in_two_columns_inside_the_window() -> void:
	var screen := await _open_in_window(Vector2i(720, 1280))
	var zoom: PortraitZoom = screen.get_node("Margin/PortraitZoom")
	assert_almost_eq(zoom.zoomed_by(), 1.3, 0.001)
	var screen_scale := screen.get_viewport().get_final_transform().get_scale().y
	var card := screen.first_card()
	var description_px := (
		card.get_theme_font_size(&"font_size", &"HintLabel") * zoom.zoomed_by() * screen_scale
	)
	assert_gte(description_px, 14.0, "a card's description is %.1f px" % description_px)
	assert_eq((screen.get_node("%Cards") as GridContainer).columns, 2)
	var content := (screen.get_node("Margin") as Control).get_global_rect()
	assert_true(
		screen.get_viewport_rect().grow(0.5).encloses(content),
		"the screen %s stays in the window %s" % [content, screen.get_viewport_rect()]
	)
	var title: Label = screen.get_node("%TitleLabel")
	assert_lte(title.get_line_count(), title.get_visible_line_count(), "the title is whole")
	screen.free()  # before its window


func test_landscape_is_laid_out_as_designed() -> void:
	var screen := await _open_in_window(Vector2i(1280, 720))
	var zoom: PortraitZoom = screen.get_node("Margin/PortraitZoom")
	assert_eq(zoom.zoomed_by(), 1.0)
	var content := (screen.get_node("Margin") as Control).get_global_rect()
	assert_eq(content, screen.get_viewport_rect(), "the content fills the window")
	screen.free()
