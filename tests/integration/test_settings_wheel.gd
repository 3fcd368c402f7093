extends GutTest
## The mouse wheel scrolls the Settings list and never moves a slider: trial 7 scrolled
## with the pointer over the tilt sensitivity slider and it went from ×1.00 to ×0.80
## unnoticed. The sliders have `scrollable = false`, so the wheel goes on to the list.

const SETTINGS_SCREEN := preload("res://scenes/menu/settings_menu.tscn")


func test_no_slider_in_settings_takes_the_wheel() -> void:
	var screen: Control = SETTINGS_SCREEN.instantiate()
	add_child_autofree(screen)
	await wait_process_frames(2)
	var sliders := screen.find_children("*", "Slider", true, false)
	assert_gte(sliders.size(), 4, "the four sliders were looked at")
	for node in sliders:
		assert_false((node as Slider).scrollable, "%s takes the wheel" % node.name)
