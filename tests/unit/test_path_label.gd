extends GutTest
## The level select's folder line keeps the end of the path in view: at 900 × 700 it read
## "Folder: /root/.local/share/godot/app_userdata/Board Studio/shots_boards/pach…", cut
## just where the folder the player looks for is named. Now it is trimmed from the start.

const LONG := "/root/.local/share/godot/app_userdata/Board Studio/boards/pachinko"


func _label(width: float) -> PathLabel:
	var label := PathLabel.new()
	add_child_autofree(label)
	label.size = Vector2(width, 24.0)
	label.show_path("Folder: ", LONG)
	return label


func _width(label: Label) -> float:
	var font := label.get_theme_font(&"font")
	var font_size := label.get_theme_font_size(&"font_size")
	return font.get_string_size(label.text, HORIZONTAL_ALIGNMENT_LEFT, -1, font_size).x


func test_a_long_path_keeps_its_end_and_fits() -> void:
	var label := _label(260.0)
	assert_true(label.text.begins_with("Folder: …/"), label.text)
	assert_true(label.text.ends_with("/boards/pachinko"), label.text)
	assert_lte(_width(label), 260.0, "fits the label")
	assert_eq(label.tooltip_text, LONG, "the whole path is the tooltip")


func test_a_path_with_room_is_shown_whole_and_refits_when_the_label_narrows() -> void:
	var label := _label(2000.0)
	assert_eq(label.text, "Folder: " + LONG)
	label.size = Vector2(150.0, 24.0)
	assert_true(label.text.ends_with("pachinko"), "narrowed: " + label.text)
	assert_lte(_width(label), 150.0)
