@tool
extends RefCounted
## Starting points for a new board, so a designer can begin from the editor alone: the
## classic machine's ring, launch rail and gutter with no pins; or an empty walled maze
## with the tutorial's cell sizes, four corner starts and the goal in the middle.

const CELL := 35.0


## Field values for a pachinko board of the classic machine's shape.
static func pachinko_settings(id: String, title: String, blurb: String) -> Dictionary:
	return {
		"kind": BoardLevel.Kind.PACHINKO,
		"board_id": "pachinko_" + id,
		"display_name": title,
		"description": blurb,
		"size": Vector2(700, 700),
		"ball_radius": 5.0,
		"tuning": TuningPresets.pachinko(),
		"ring_center": Vector2(350, 350),
		"ring_radius": 330.0,
		"rail_width": 20.0,
		"rail_start_deg": 40.0,
		"rail_end_deg": -55.0,
		"gutter_start_deg": 60.0,
		"gutter_end_deg": 120.0,
		"gutter_bounces": 7,
		"pin_radius": 1.5,
		"cup_start_balls": 25,
	}


## Field values for a maze of `cells` with the tutorial's corridor and wall sizes.
static func maze_settings(id: String, title: String, blurb: String, cells: Vector2i) -> Dictionary:
	var size := Vector2(cells) * CELL
	return {
		"kind": BoardLevel.Kind.MAZE,
		"board_id": "maze_" + id,
		"display_name": title,
		"description": blurb,
		"size": size,
		"ball_radius": 5.0,
		"tuning": TuningPresets.maze(),
		"grid_cols": cells.x,
		"grid_rows": cells.y,
		"path_width": CELL - 10.0,
		"wall_width": 10.0,
		"goal_center": size * 0.5,
		"goal_radius": 32.5,
		"hole_radius": 9.0,
	}


## A new board of `kind` (BoardLevel.Kind), ready to edit and to play.
static func make(kind: int) -> BoardLevel:
	var level := BoardLevel.new()
	var settings: Dictionary
	if kind == BoardLevel.Kind.MAZE:
		var cells := Vector2i(10, 9)
		settings = maze_settings("untitled", "Untitled maze", "A new maze.", cells)
		var far := Vector2(cells) * CELL
		level.walls = PackedVector2Array(
			(
				[Vector2.ZERO, Vector2(far.x, 0), Vector2(far.x, 0), far, far, Vector2(0, far.y)]
				+ [Vector2(0, far.y), Vector2.ZERO]
			)
		)
		var half := Vector2.ONE * CELL * 0.5
		level.ball_starts = PackedVector2Array(
			[
				half,
				Vector2(far.x, 0) + half * Vector2(-1, 1),
				far - half,
				Vector2(0, far.y) + half * Vector2(1, -1)
			]
		)
	else:
		settings = pachinko_settings("untitled", "Untitled machine", "A new pachinko machine.")
	for key: String in settings:
		level.set(key, settings[key])
	return level


## A free level path for `level`: levels/<kind>/<id>.board, numbered if taken.
static func free_path(level: BoardLevel) -> String:
	var kind := BoardLevel.kind_name(level.kind)
	var id := level.board_id.trim_prefix(kind + "_").validate_filename().to_snake_case()
	if id.is_empty():
		id = "untitled"
	var path := "res://levels/%s/%s.board" % [kind, id]
	var n := 2
	while ResourceLoader.exists(path) or FileAccess.file_exists(path):
		path = "res://levels/%s/%s_%d.board" % [kind, id, n]
		n += 1
	return path
