extends SceneTree
## Draws the project's icon.svg as a 256 x 256 PNG for the release folder's .desktop entry.
## Usage: godot --headless --path . -s res://tools/release/icon_png.gd -- OUT.png

const SIZE := 256


func _init() -> void:
	var args := OS.get_cmdline_user_args()
	if args.size() != 1:
		printerr("usage: -s res://tools/release/icon_png.gd -- OUT.png")
		quit(2)
		return
	var svg := FileAccess.get_file_as_string("res://icon.svg")
	var probe := Image.new()
	if svg.is_empty() or probe.load_svg_from_string(svg) != OK:
		printerr("icon.svg could not be read")
		quit(1)
		return
	var image := Image.new()
	image.load_svg_from_string(svg, float(SIZE) / probe.get_width())
	var status := image.save_png(args[0])
	if status != OK:
		printerr("could not write %s (%s)" % [args[0], error_string(status)])
	quit(0 if status == OK else 1)
