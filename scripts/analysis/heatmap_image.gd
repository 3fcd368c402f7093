class_name HeatmapImage
extends RefCounted
## Draws where balls went as a picture: the density grid of an analysis, smoothed to the
## board's size, on a dark ground with the ring, pins and pocket mouths drawn faintly over
## it so the hot spots can be placed. Counts go through a log scale (the rail and the
## gutter see far more ball-time than a quiet corner). Model code: it only fills an Image.

## Colours from no balls to the most: dark, blue, red, orange, pale yellow.
const RAMP: Array[Color] = [
	Color(0.06, 0.06, 0.09),
	Color(0.13, 0.22, 0.55),
	Color(0.75, 0.18, 0.25),
	Color(0.98, 0.55, 0.12),
	Color(1.0, 0.95, 0.7),
]
const BOARD_INK := Color(1.0, 1.0, 1.0, 0.35)
const POCKET_INK := Color(0.55, 1.0, 0.6, 0.8)
## Pixels per grid cell side in the overlay picture.
const OVERLAY_ZOOM := 4
## The largest picture side, px (bigger boards are drawn smaller).
const MAX_SIDE := 1024


## The heat map of `tally` on `level`, at the board's size (at most MAX_SIDE a side).
static func render(level: BoardLevel, tally: AnalysisTally) -> Image:
	var grid := tally.grid_size
	var img := Image.create(grid.x, grid.y, false, Image.FORMAT_RGBA8)
	var peak := 0
	for c in tally.density:
		peak = maxi(peak, c)
	var scale := 1.0 / log(1.0 + peak) if peak > 0 else 0.0
	for y in grid.y:
		for x in grid.x:
			var t := log(1.0 + tally.density[y * grid.x + x]) * scale
			img.set_pixel(x, y, ramp(t))
	var side := maxf(level.size.x, level.size.y)
	var zoom := minf(1.0, MAX_SIDE / side) if side > 0.0 else 1.0
	var out_size := Vector2i(maxi(int(level.size.x * zoom), 1), maxi(int(level.size.y * zoom), 1))
	img.resize(out_size.x, out_size.y, Image.INTERPOLATE_BILINEAR)
	_draw_board(img, level, zoom)
	return img


## The density alone on a clear ground, for drawing over the board itself: OVERLAY_ZOOM
## pixels a grid cell, smoothed (the editor's overlay scales it to the board).
static func render_overlay(tally: AnalysisTally) -> Image:
	var grid := tally.grid_size
	var img := Image.create(grid.x, grid.y, false, Image.FORMAT_RGBA8)
	var peak := 0
	for c in tally.density:
		peak = maxi(peak, c)
	var scale := 1.0 / log(1.0 + peak) if peak > 0 else 0.0
	for y in grid.y:
		for x in grid.x:
			var t := log(1.0 + tally.density[y * grid.x + x]) * scale
			var colour := ramp(t)
			colour.a = clampf(t * 1.6, 0.0, 0.8)
			img.set_pixel(x, y, colour)
	img.resize(grid.x * OVERLAY_ZOOM, grid.y * OVERLAY_ZOOM, Image.INTERPOLATE_BILINEAR)
	return img


## The ramp colour at t in 0..1.
static func ramp(t: float) -> Color:
	var x := clampf(t, 0.0, 1.0) * (RAMP.size() - 1)
	var i := mini(int(x), RAMP.size() - 2)
	return RAMP[i].lerp(RAMP[i + 1], x - i)


static func _draw_board(img: Image, level: BoardLevel, zoom: float) -> void:
	if level.ring_radius > 0.0:
		var steps := int(TAU * level.ring_radius * zoom)
		for k in steps:
			var at := level.ring_center + Vector2.from_angle(TAU * k / steps) * level.ring_radius
			_blend(img, at * zoom, BOARD_INK)
	for pin in level.pins:
		_blend(img, pin * zoom, BOARD_INK)
	for spec: PocketSpec in level.pockets:
		if spec == null:
			continue
		var half := spec.width * 0.5
		for k in int(spec.width * zoom) + 1:
			var at := spec.position + Vector2(-half + k / zoom, 0.0)
			_blend(img, at * zoom, POCKET_INK)


static func _blend(img: Image, at: Vector2, ink: Color) -> void:
	var p := Vector2i(at.floor())
	if p.x < 0 or p.y < 0 or p.x >= img.get_width() or p.y >= img.get_height():
		return
	img.set_pixelv(p, img.get_pixelv(p).blend(ink))
