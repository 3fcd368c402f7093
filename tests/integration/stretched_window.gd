extends RefCounted
## A window that stretches its content as the project's own window does (the 1280 × 720
## design, canvas_items, expand), for tests that measure what a player sees at a screen size.

## The project's design size (display/window/size in project.godot).
const DESIGN_SIZE := Vector2i(1280, 720)


## A new Window of `size` pixels, stretched like the project's. The caller adds it to the
## tree (a GutTest: add_child_autofree) and puts the screen under test in it.
static func make(size: Vector2i) -> Window:
	var window := Window.new()
	window.size = size
	window.content_scale_size = DESIGN_SIZE
	window.content_scale_mode = Window.CONTENT_SCALE_MODE_CANVAS_ITEMS
	window.content_scale_aspect = Window.CONTENT_SCALE_ASPECT_EXPAND
	return window


## `scene` made in a new window of `size` (see make()) that `test` frees after the test,
## after `frames` frames. `prepare` (optional) gets the new node before it enters the tree.
static func open(
	test: GutTest, scene: PackedScene, size: Vector2i, frames: int, prepare := Callable()
) -> Node:
	var window := make(size)
	test.add_child_autofree(window)
	var node := scene.instantiate()
	if prepare.is_valid():
		prepare.call(node)
	window.add_child(node)
	await test.wait_process_frames(frames)
	return node


## Screen pixels one unit of font size takes when `control` draws it: its own scale times
## the window's stretch.
static func px_per_font_unit(control: Control) -> float:
	var drawn := control.get_global_transform_with_canvas().get_scale().y
	return drawn * control.get_viewport().get_final_transform().get_scale().y
