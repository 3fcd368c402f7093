extends GutTest
## The title screen, the settings screen and the pause menu read on a phone: the project
## draws its 1280 × 720 design at 0.56 on a 720 × 1280 screen, which made the hints and the
## settings' column headers 11 px, the settings' labels 13.5 px. Now the screens are drawn
## bigger in a portrait window (PortraitZoom) and the settings' rows get narrower to fit:
## every visible label and button is at least 14 px on the screen, and the screens stay whole
## in the window at 720 × 1280, 900 × 700 and 1280 × 720.

const MainMenuScene := preload("res://scenes/menu/main_menu.tscn")
const SettingsScene := preload("res://scenes/menu/settings_menu.tscn")
const PauseScene := preload("res://scenes/common/pause_menu.tscn")
const StretchedWindow := preload("res://tests/integration/stretched_window.gd")
const SIZES: Array[Vector2i] = [Vector2i(720, 1280), Vector2i(900, 700), Vector2i(1280, 720)]
const MIN_SCREEN_PX := 14.0


## `scene` in a window of `size` pixels, stretched as the project stretches its own window.
func _open_in_window(scene: PackedScene, size: Vector2i) -> Control:
	return await StretchedWindow.open(self, scene, size, 5) as Control


## How tall `control`'s text is on the screen, in pixels.
static func screen_px(control: Control) -> float:
	return MazeSideText.font_size_of(control) * StretchedWindow.px_per_font_unit(control)


## Asserts every visible label and button under `root` reads at MIN_SCREEN_PX; returns how
## many were looked at.
func _assert_readable(root: Control, where: String) -> int:
	var checked := 0
	for node in root.find_children("*", "Control", true, false):
		var control := node as Control
		if not control.is_visible_in_tree() or not (control is Label or control is Button):
			continue
		checked += 1
		var px := screen_px(control)
		assert_gte(px, MIN_SCREEN_PX, "%s: %s is %.1f px" % [where, control.name, px])
	return checked


## Asserts `content` is inside the window and as big as its content needs.
func _assert_whole(content: Control, where: String) -> void:
	var view := content.get_viewport_rect()
	var rect := content.get_global_rect()
	assert_true(view.grow(0.5).encloses(rect), "%s: %s is in the window %s" % [where, rect, view])
	var needed := content.get_combined_minimum_size()
	assert_lte(needed.x, content.size.x + 0.5, "%s: its content fits across" % where)
	assert_lte(needed.y, content.size.y + 0.5, "%s: and down" % where)


func test_the_title_screen_reads_at_14_px_and_stays_whole() -> void:
	for size in SIZES:
		var menu := await _open_in_window(MainMenuScene, size)
		var checked := _assert_readable(menu, "title screen %s" % size)
		assert_gte(checked, 8, "the title, subtitle, buttons, hint and version were looked at")
		_assert_whole(menu.get_node("Content") as Control, "title screen %s" % size)
		var hint: Label = menu.get_node("%Hint")
		var hint_rect := hint.get_global_rect()
		assert_true(
			menu.get_viewport_rect().encloses(hint_rect), "%s: the hint is in the window" % size
		)
		menu.free()  # before its window


func test_the_settings_read_at_14_px_and_stay_whole() -> void:
	for size in SIZES:
		var settings := await _open_in_window(SettingsScene, size)
		var checked := _assert_readable(settings, "settings %s" % size)
		assert_gte(checked, 40, "every row, binding and the hint were looked at")
		_assert_whole(settings.get_node("Margin") as Control, "settings %s" % size)
		var scroll: ScrollContainer = settings.get_node("Margin/Panel/Box/Scroll")
		assert_false(
			scroll.get_h_scroll_bar().visible, "%s: the settings need no sideways scroll" % size
		)
		settings.free()


func test_the_pause_menu_reads_at_14_px_on_a_phone() -> void:
	for size in SIZES:
		var window := StretchedWindow.make(size)
		add_child_autofree(window)
		var pause := PauseScene.instantiate() as CanvasLayer
		window.add_child(pause)
		var dim := pause.get_node("Dim") as Control
		dim.visible = true  # as when it opens, without pausing the test's tree
		await wait_process_frames(4)
		var checked := _assert_readable(dim, "pause menu %s" % size)
		assert_eq(checked, 7, "the title, five buttons and the hint were looked at")
		var panel := pause.get_node("Dim/Center/Panel") as Control
		assert_true(
			dim.get_viewport_rect().encloses(panel.get_global_rect()),
			"%s: the menu is in the window" % size
		)
		pause.free()
