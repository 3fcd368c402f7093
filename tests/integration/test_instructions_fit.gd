extends GutTest
## The pachinko instructions card is readable on a portrait phone: the project draws its
## 1280 × 720 design at 0.56 on a 720 × 1280 screen, which made the card's text 8-9 px.
## Now the card is scaled up so its smallest text is 14 px on the screen, and it stays
## inside the board's area; at 1280 × 720 it is drawn at its design size.

const PANEL := preload("res://scenes/pachinko/instructions_panel.tscn")
const StretchedWindow := preload("res://tests/integration/stretched_window.gd")


## The panel over the board's area (the game's portrait or landscape one) in a window of
## `size` pixels stretched as the project stretches its window.
func _panel_in_window(size: Vector2i) -> InstructionsPanel:
	var window := StretchedWindow.make(size)
	add_child_autofree(window)
	var panel: InstructionsPanel = PANEL.instantiate()
	window.add_child(panel)
	var view := window.get_visible_rect().size
	var side := minf(view.x, view.y) - 32.0
	panel.set_anchors_preset(Control.PRESET_TOP_LEFT)
	panel.position = Vector2(16.0, 16.0)
	panel.size = Vector2(side, side) if view.y > view.x else Vector2(view.x - 400.0, side)
	panel.show_start(BoardLoader.load_board("res://levels/pachinko/classic.board").level)
	await wait_process_frames(3)
	return panel


func test_the_card_reads_at_14_px_in_portrait_and_stays_in_its_area() -> void:
	var panel := await _panel_in_window(Vector2i(720, 1280))
	var screen_scale := panel.get_viewport().get_final_transform().get_scale().y
	var smallest_px := InstructionsPanel.SMALLEST_FONT * panel.card_scale() * screen_scale
	assert_gte(smallest_px, 13.99, "the legend's text is %.1f px" % smallest_px)
	var card: Control = panel.get_node("Card")
	assert_true(
		panel.get_global_rect().encloses(card.get_global_rect()),
		"the card %s stays in the area %s" % [card.get_global_rect(), panel.get_global_rect()]
	)
	panel.free()  # before its window


func test_the_card_keeps_its_design_size_at_1280_by_720() -> void:
	var panel := await _panel_in_window(Vector2i(1280, 720))
	assert_eq(panel.card_scale(), 1.0)
	panel.free()
