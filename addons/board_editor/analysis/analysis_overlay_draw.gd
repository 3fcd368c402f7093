@tool
extends RefCounted
## Draws a play analysis over the board in the 2D viewport: the heat map under everything,
## each pocket's catch rate with its 95% interval (dead pockets in red), and a card in the
## board's top-left corner with the return and the aim map (how often each power band's
## shots land in each pocket).

const CARD_INK := Color(0.05, 0.06, 0.09, 0.86)
const TEXT_INK := Color(0.95, 0.95, 0.97)
const DIM_INK := Color(0.7, 0.72, 0.78)
const DEAD_INK := Color(1.0, 0.42, 0.38)
const AIM_INK := Color(0.35, 1.0, 0.55)
const FONT_SIZE := 13
const LINE := 17.0
const CELL := 22.0
## How strongly the heat map covers the board.
const HEAT_ALPHA := 0.8


## Draws `report` (an AnalysisReport dictionary, fresh or from the cache) and the heat map
## texture `heat` (may be null) for `level`; `to_screen` maps board pixels to `canvas`.
static func draw(
	canvas: Control, to_screen: Transform2D, level: BoardLevel, report: Dictionary, heat: Texture2D
) -> void:
	if heat != null:
		canvas.draw_set_transform_matrix(to_screen)
		canvas.draw_texture_rect(
			heat, Rect2(Vector2.ZERO, level.size), false, Color(1, 1, 1, HEAT_ALPHA)
		)
		canvas.draw_set_transform_matrix(Transform2D.IDENTITY)
	if report.is_empty():
		return
	var dead: Array = report.get("dead_pockets", [])
	var pockets: Array = report.get("pockets", [])
	for i in mini(pockets.size(), level.pockets.size()):
		var pocket: Dictionary = pockets[i]
		var at := to_screen * (level.pockets[i].position - Vector2(0, 14))
		var is_dead := dead.has(float(i)) or dead.has(i)
		var text := (
			"%.1f%% ±%.1f"
			% [
				AnalysisReport.number(pocket.get("rate", 0.0)) * 100.0,
				AnalysisReport.number(pocket.get("ci95", 0.0)) * 100.0
			]
		)
		_label(canvas, at, ("dead " if is_dead else "") + text, DEAD_INK if is_dead else TEXT_INK)
	_card(canvas, to_screen * Vector2.ZERO + Vector2(8, 8), report, pockets.size())


static func _label(canvas: Control, centre: Vector2, text: String, ink: Color) -> void:
	var font := ThemeDB.fallback_font
	var width := font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, FONT_SIZE).x
	var box := Rect2(centre - Vector2(width * 0.5 + 4, LINE - 3), Vector2(width + 8, LINE + 2))
	canvas.draw_rect(box, CARD_INK)
	canvas.draw_string(
		font,
		box.position + Vector2(4, LINE - 3),
		text,
		HORIZONTAL_ALIGNMENT_LEFT,
		-1,
		FONT_SIZE,
		ink
	)


# The summary card: shots, return ± CI, aim distance, and the aim map grid.
static func _card(canvas: Control, at: Vector2, report: Dictionary, pocket_count: int) -> void:
	var font := ThemeDB.fallback_font
	var bands: Array = report.get("bands", [])
	var lines: Array[String] = [
		"Play analysis: %d shots" % roundi(AnalysisReport.number(report.get("shots", 0))),
		(
			"Return %.2f ± %.2f balls per ball"
			% [
				AnalysisReport.number(report.get("return", 0.0)),
				AnalysisReport.number(report.get("return_ci95", 0.0))
			]
		),
	]
	var aim := AnalysisReport.number(report.get("aim_tv", -1.0))
	lines.append("Aim: weakest vs strongest %s" % ("%.2f of 1" % aim if aim >= 0.0 else "unknown"))
	var width := 52.0 + CELL * pocket_count
	for text in lines:
		width = maxf(width, font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, FONT_SIZE).x)
	var size := Vector2(width + 12.0, LINE * (lines.size() + 1) + CELL * bands.size() + 10.0)
	canvas.draw_rect(Rect2(at, size), CARD_INK)
	var y := at.y + LINE
	for text in lines:
		canvas.draw_string(
			font, Vector2(at.x + 6, y), text, HORIZONTAL_ALIGNMENT_LEFT, -1, FONT_SIZE, TEXT_INK
		)
		y += LINE
	for p in pocket_count:
		var x := at.x + 52.0 + CELL * p
		canvas.draw_string(
			font,
			Vector2(x + 6, y),
			str(p + 1),
			HORIZONTAL_ALIGNMENT_LEFT,
			-1,
			FONT_SIZE - 1,
			DIM_INK
		)
	y += 4.0
	var peak := 0.0
	for band: Dictionary in bands:
		for rate: Variant in band.get("pocket_rates", []):
			peak = maxf(peak, AnalysisReport.number(rate))
	for band: Dictionary in bands:
		var label := (
			"%d–%d"
			% [
				roundi(AnalysisReport.number(band.get("power_from", 0))),
				roundi(AnalysisReport.number(band.get("power_to", 0)))
			]
		)
		canvas.draw_string(
			font,
			Vector2(at.x + 6, y + CELL - 7),
			label,
			HORIZONTAL_ALIGNMENT_LEFT,
			-1,
			FONT_SIZE - 1,
			DIM_INK
		)
		var rates: Array = band.get("pocket_rates", [])
		for p in mini(rates.size(), pocket_count):
			var share := AnalysisReport.number(rates[p]) / peak if peak > 0.0 else 0.0
			var cell := Rect2(Vector2(at.x + 52.0 + CELL * p, y), Vector2(CELL - 3, CELL - 3))
			canvas.draw_rect(cell, Color(AIM_INK, 0.08 + 0.9 * share))
		y += CELL
