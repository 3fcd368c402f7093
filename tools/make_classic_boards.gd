extends SceneTree
## Writes the two shipped classic boards from their recipes:
##   tools/godot.sh --headless --path . -s tools/make_classic_boards.gd
## levels/pachinko/classic.board: a ring machine in the spirit of the Flash chapter.
## levels/maze/classic.board: the tilt maze tutorial's exact layout (its goal ring made to fit).

const PACHINKO_PATH := "res://levels/pachinko/classic.board"
const MAZE_PATH := "res://levels/maze/classic.board"

# The maze tutorial's walls as (column, row, horizontal, length) in cells of 35 px.
const MAZE_CELL := 35.0
const MAZE_WALLS := [
	[0, 0, true, 10],
	[0, 0, false, 9],
	[0, 9, true, 10],
	[10, 0, false, 9],
	[0, 6, true, 1],
	[0, 8, true, 1],
	[1, 1, true, 2],
	[1, 7, true, 1],
	[2, 2, true, 2],
	[2, 4, true, 1],
	[2, 5, true, 1],
	[2, 6, true, 1],
	[3, 3, true, 1],
	[3, 8, true, 3],
	[4, 6, true, 1],
	[5, 2, true, 2],
	[5, 7, true, 1],
	[6, 1, true, 1],
	[6, 6, true, 2],
	[7, 3, true, 2],
	[7, 7, true, 2],
	[8, 1, true, 1],
	[8, 2, true, 1],
	[8, 3, true, 1],
	[8, 4, true, 2],
	[8, 8, true, 2],
	[1, 1, false, 2],
	[1, 4, false, 2],
	[2, 2, false, 2],
	[2, 5, false, 1],
	[2, 7, false, 2],
	[3, 0, false, 1],
	[3, 4, false, 1],
	[3, 6, false, 2],
	[4, 1, false, 2],
	[4, 6, false, 1],
	[5, 0, false, 2],
	[5, 6, false, 1],
	[5, 8, false, 1],
	[6, 4, false, 1],
	[6, 6, false, 1],
	[7, 1, false, 4],
	[7, 7, false, 2],
	[8, 2, false, 1],
	[8, 4, false, 2],
	[9, 1, false, 1],
	[9, 5, false, 2],
]
const MAZE_STARTS := [[0, 0], [9, 0], [0, 8], [9, 8]]
const MAZE_HOLES := [[0, 5], [2, 0], [2, 4], [4, 6], [6, 2], [6, 8], [8, 1], [8, 2]]

# Pachinko: five pockets (mouth centre x, y, payout). They paid six each (the chapter paid
# four), and a held handle strength that fed the middle paid 1.6 balls a ball: now the side
# pair, which every strength reaches least, pay most, so no strength pays much more than
# another (tools/power_returns.gd; the return at uniform power stays about 0.85).
const POCKETS := [
	[350.0, 300.0, 3],
	[215.0, 390.0, 10],
	[485.0, 390.0, 10],
	[285.0, 515.0, 2],
	[415.0, 515.0, 2],
]
const POCKET_WIDTH := 22.0
const POCKET_DEPTH := 24.0
const PIN_SPACING := Vector2(26.0, 24.0)
# Field pins stay this far inside the guide arc, so a ball can pass between them and it.
const FIELD_MARGIN := 20.0


func _initialize() -> void:
	var ok := _save(make_pachinko(), PACHINKO_PATH) and _save(make_maze(), MAZE_PATH)
	quit(0 if ok else 1)


## The classic pachinko machine.
static func make_pachinko() -> BoardLevel:
	var level := BoardLevel.new()
	level.kind = BoardLevel.Kind.PACHINKO
	level.board_id = "pachinko_classic"
	level.display_name = "Classic"
	# at most 80 characters: a board file's lines stay under 100 (test_board_format.gd)
	var payouts := "the side pair pay ten balls, the top one three, the low pair two."
	level.description = "Five pockets: " + payouts
	level.size = Vector2(700, 700)
	level.ball_radius = 5.0
	level.tuning = TuningPresets.pachinko()
	level.ring_center = Vector2(350, 350)
	level.ring_radius = 330.0
	level.rail_width = 20.0
	level.rail_start_deg = 40.0
	level.rail_end_deg = LaunchRail.AIMING_END_DEG
	level.gutter_start_deg = 60.0
	level.gutter_end_deg = 120.0
	level.gutter_bounces = 7
	level.pin_radius = 1.5
	level.cup_start_balls = 25
	level.fascia = FasciaNames.CLASSIC
	var pockets: Array[PocketSpec] = []
	for mouth: Array in POCKETS:
		var at := Vector2(_number(mouth, 0), _number(mouth, 1))
		var payout := int(_number(mouth, 2))
		pockets.append(PocketSpec.create(at, POCKET_WIDTH, POCKET_DEPTH, payout))
	level.pockets = pockets
	# Field pins: a staggered lattice inside the guide arc, cleared around each pocket.
	var field_radius := LaunchRail.guide_radius(level) - FIELD_MARGIN
	var area := Rect2(
		level.ring_center - Vector2.ONE * field_radius, Vector2.ONE * field_radius * 2
	)
	var field := PinPatterns.staggered_lattice(area, PIN_SPACING)
	field = PinPatterns.inside_circle(field, level.ring_center, field_radius)
	var keep_out: Array[Rect2] = []
	var margin := level.ball_radius * 2.0 + level.pin_radius + 2.0
	for spec in pockets:
		keep_out.append(
			Rect2(
				spec.position - Vector2(spec.width * 0.5 + margin, margin),
				Vector2(spec.width + margin * 2.0, spec.depth + margin * 2.0)
			)
		)
	field = PinPatterns.outside_rects(field, keep_out)
	var clear_lane := PackedVector2Array()
	for at in field:
		if not LaunchRail.in_flight_lane(level, at):
			clear_lane.append(at)
	field = clear_lane
	level.pins = field
	var owners := PackedInt32Array()
	owners.resize(field.size())
	owners.fill(-1)
	level.pin_pocket = owners
	var special := PackedByteArray()
	special.resize(field.size())
	level.pin_special = special
	for i in pockets.size():
		PocketStamp.apply(level, i)
	return level


## The tilt maze tutorial's board, converted exactly as the tutorial does.
static func make_maze() -> BoardLevel:
	var level := BoardLevel.new()
	level.kind = BoardLevel.Kind.MAZE
	level.board_id = "maze_classic"
	level.display_name = "Classic"
	level.description = "Roll all four balls into the centre. Hard mode adds eight black holes."
	level.size = Vector2(350, 315)
	level.ball_radius = 5.0
	level.tuning = TuningPresets.maze_seed()
	level.grid_cols = 10
	level.grid_rows = 9
	level.path_width = 25.0
	level.wall_width = 10.0
	var walls := PackedVector2Array()
	for wall: Array in MAZE_WALLS:
		var start := Vector2(_number(wall, 0), _number(wall, 1)) * MAZE_CELL
		var length := _number(wall, 3) * MAZE_CELL
		var horizontal: bool = wall[2]
		walls.append(start)
		walls.append(start + (Vector2(length, 0) if horizontal else Vector2(0, length)))
	level.walls = walls
	level.ball_starts = _cell_centres(MAZE_STARTS)
	level.goal_center = Vector2(350.0 / 2.0, 315.0 / 2.0)
	# The tutorial's ring is 65 px across, drawn under its room's walls (their faces stand 30
	# px from the centre): the generated mazes' ring fits the same room with its lip clear.
	level.goal_radius = MazeGenerator.GOAL_RADIUS
	level.holes = _cell_centres(MAZE_HOLES)
	level.hole_radius = 9.0
	return level


static func _cell_centres(cells: Array) -> PackedVector2Array:
	var points := PackedVector2Array()
	for cell: Array in cells:
		var at := Vector2(_number(cell, 0), _number(cell, 1))
		points.append(at * MAZE_CELL + Vector2.ONE * MAZE_CELL * 0.5)
	return points


# Entry `index` of a recipe row, as a float (rows mix ints, floats and bools).
static func _number(row: Array, index: int) -> float:
	var value: float = row[index]
	return value


static func _save(level: BoardLevel, path: String) -> bool:
	MedalRule.keep_file_medals(level, path)
	var error := ResourceSaver.save(level, path)
	if error != OK:
		push_error("make_classic_boards: could not write %s (%s)" % [path, error_string(error)])
		return false
	print("wrote %s" % path)
	return true
