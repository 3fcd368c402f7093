@tool
extends RefCounted
## Draws a maze play analysis over the board in the 2D viewport: where and why the pilot
## lost its games (MazeLossDraw; for an older report, a red ring round every hole that
## swallowed balls in hard mode), and a card at the board's top-left corner with each
## mode's solve rate and median time. Also words the figures for the dock.

const MazeLossDraw := preload("res://addons/board_editor/analysis/maze_loss_draw.gd")
const CARD_INK := Color(0.05, 0.06, 0.09, 0.86)
const TEXT_INK := Color(0.95, 0.95, 0.97)
const HOLE_INK := Color(1.0, 0.42, 0.38)
const FONT_SIZE := 13
const LINE := 17.0


## Draws `report` (a MazeAnalysis report) for `level`; `to_screen` maps board pixels to
## `canvas`.
static func draw(
	canvas: Control, to_screen: Transform2D, level: BoardLevel, report: Dictionary
) -> void:
	var font := ThemeDB.fallback_font
	var scale := to_screen.get_scale().x
	var hard: Dictionary = report.get("hard", {})
	var holes: Array = hard.get("holes", [])
	if report.has("losses"):
		MazeLossDraw.draw(canvas, to_screen, level, report)
		holes = []  # the losses mark the holes that caught balls too
	for hole: Dictionary in holes:
		var index: int = hole.get("index", -1)
		var balls: int = hole.get("balls", 0)
		if index < 0 or index >= level.holes.size():
			continue  # a report of another version of the board
		var centre := to_screen * level.holes[index]
		var radius := (level.hole_radius + 6.0) * scale
		canvas.draw_arc(centre, radius, 0.0, TAU, 40, HOLE_INK, 2.5, true)
		var text := "%d ball%s" % [balls, "" if balls == 1 else "s"]
		var at := centre + Vector2(radius + 3.0, FONT_SIZE * 0.4)
		var width := font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, FONT_SIZE).x
		canvas.draw_rect(Rect2(at - Vector2(3, LINE - 4), Vector2(width + 6, LINE)), CARD_INK)
		canvas.draw_string(font, at, text, HORIZONTAL_ALIGNMENT_LEFT, -1, FONT_SIZE, HOLE_INK)
	var lines: Array[String] = ["Play analysis: the autoplay pilot"]
	for mode: String in ["easy", "hard"]:
		var figures: Dictionary = report.get(mode, {})
		lines.append(mode_line(mode, figures))
	var card_width := 0.0
	for text in lines:
		card_width = maxf(
			card_width, font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, FONT_SIZE).x
		)
	# Above the board when the view has room there, so the card hides none of the maze.
	var card_size := Vector2(card_width + 12, LINE * lines.size() + 8)
	var corner := to_screen * Vector2.ZERO + Vector2(0, -card_size.y - 6)
	if corner.y < 4.0:
		corner = to_screen * Vector2.ZERO + Vector2(8, 8)
	canvas.draw_rect(Rect2(corner, card_size), CARD_INK)
	for i in lines.size():
		var at := corner + Vector2(6, LINE * (i + 1))
		canvas.draw_string(font, at, lines[i], HORIZONTAL_ALIGNMENT_LEFT, -1, FONT_SIZE, TEXT_INK)


## One mode's figures in words: "Hard: won 5 of 6, median 41.2 s".
static func mode_line(mode: String, figures: Dictionary) -> String:
	var games: int = figures.get("games", 0)
	var wins: int = figures.get("wins", 0)
	var median: float = figures.get("median_time_s", 0.0)
	var line := "%s: won %d of %d" % [mode.capitalize(), wins, games]
	if wins > 0:
		line += ", median %.1f s" % median
	return line


## The holes that caught balls in words: "Balls lost in hard mode: hole 3 (2), hole 5 (1)".
static func holes_line(holes: Array) -> String:
	var parts := PackedStringArray()
	for hole: Dictionary in holes:
		var id: int = hole.get("id", 0)
		var balls: int = hole.get("balls", 0)
		parts.append("hole %d (%d)" % [id, balls])
	return "Balls lost in hard mode: " + ", ".join(parts)
