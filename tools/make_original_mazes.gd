extends RefCounted
## The two original mazes for tools/make_original_boards.gd, built with the board editor's
## actions (walls, black holes, ball starts, the goal; mirror mode for the courtyards).

const ActionHistory := preload("res://addons/board_editor/core/action_history.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const Mirror := preload("res://addons/board_editor/core/mirror.gd")
const NewBoard := preload("res://addons/board_editor/core/new_board.gd")
const SetPropertiesAction := preload("res://addons/board_editor/actions/set_properties_action.gd")
const WallAction := preload("res://addons/board_editor/actions/wall_action.gd")
const AddItemsAction := preload("res://addons/board_editor/actions/add_items_action.gd")

const CELL := 35.0
const CATACOMBS_SEED := 20240611
## The teaching boards' goal radius (px): the dish and the lip the floor draws round it fit
## the 25 px corridor's dead end (12.5 − 2), and still hold two balls in a row (20 px). At 14
## the dish was drawn half under the corridor's walls.
const FOLD_GOAL_RADIUS := 10.5
## Share of the carved maze's inner walls knocked out again.
const OPENNESS := 0.2


## Catacombs: 12 x 9 cells of twisting corridors carved from a fixed seed, a few loops so
## no route is forced past a hole, a two-by-two goal room in the middle and black holes
## waiting in the dead ends. (It was 14 x 12 until the camera showed the whole board: its
## balls were then under 14 px at 1280 x 720.)
static func make_catacombs() -> BoardLevel:
	var history := ActionHistory.new()
	var cols := 12
	var rows := 9
	var level := maze_base(
		history,
		"catacombs",
		"Catacombs",
		"Twelve by nine cells of winding passages; in hard mode the dead ends hold holes.",
		Vector2i(cols, rows)
	)
	# the goal room's top left cell; the goal sits on its middle grid point
	var room := Vector2i(cols / 2 - 1, rows / 2 - 1)
	history.commit(
		SetPropertiesAction.new(level, {"goal_center": Vector2(room + Vector2i.ONE) * CELL}, "Goal")
	)
	var rng := RandomNumberGenerator.new()
	rng.seed = CATACOMBS_SEED
	# Wall flags: horizontal[r][c] is the wall on grid line y = r above cell (c, r);
	# vertical[c][r] the wall on grid line x = c left of cell (c, r).
	var horizontal := _grid(rows + 1, cols)
	var vertical := _grid(cols + 1, rows)
	# The goal room: its four cells open into each other.
	horizontal[room.y + 1][room.x] = false
	horizontal[room.y + 1][room.x + 1] = false
	vertical[room.x + 1][room.y] = false
	vertical[room.x + 1][room.y + 1] = false
	_carve(rng, cols, rows, room, horizontal, vertical)
	# Knock out a share of the inner walls: loops let the four balls (which all roll the
	# same way) find common routes, and no hole guards the only way through.
	for r in range(1, rows):
		for c in cols:
			if rng.randf() < OPENNESS:
				horizontal[r][c] = false
	for c in range(1, cols):
		for r in rows:
			if rng.randf() < OPENNESS:
				vertical[c][r] = false
	for wall in _merged_walls(horizontal, vertical, cols, rows):
		history.commit(WallAction.new(level, wall[0], wall[1]))
	var starts := BoardItems.empty_set()
	starts["starts"] = _centres([Vector2i(0, 0), Vector2i(cols - 1, 0)])
	history.commit(AddItemsAction.new(level, Mirror.mirror_set(starts, level.size.x * 0.5)))
	var bottom := BoardItems.empty_set()
	bottom["starts"] = _centres([Vector2i(0, rows - 1), Vector2i(cols - 1, rows - 1)])
	history.commit(AddItemsAction.new(level, bottom, "Add ball start"))
	var holes := BoardItems.empty_set()
	holes["holes"] = _centres(_dead_ends(horizontal, vertical, cols, rows).slice(0, 8))
	history.commit(AddItemsAction.new(level, holes, "Add black hole"))
	# The goal room is two cells wide, like a generated maze's: the generator's ring fits
	# inside it with its dashed line clear of the room's walls.
	history.commit(
		SetPropertiesAction.new(level, {"goal_radius": MazeGenerator.GOAL_RADIUS}, "Goal ring")
	)
	return refuse_wall_in_goal_ring(level)


## Courtyards: two square rings and the goal room, two cells apart, entered through gaps
## that alternate top and bottom, with one-cell chicanes in the corridors. Every wall after
## the border was drawn once on the left half in mirror mode. (It was 12 x 12 with a third
## ring until the camera showed the whole board: its balls were then 12 px at 1280 x 720.)
static func make_courtyards() -> BoardLevel:
	var history := ActionHistory.new()
	var level := maze_base(
		history,
		"courtyards",
		"Courtyards",
		"Wide square corridors spiral in to the goal; chicanes make you tilt with care.",
		Vector2i(10, 10)
	)
	var axis := level.size.x * 0.5
	# Border (the whole square; drawn in halves with mirror mode).
	var left_half := [
		[Vector2(0, 0), Vector2(5, 0)],
		[Vector2(0, 0), Vector2(0, 10)],
		[Vector2(0, 10), Vector2(5, 10)],
		# Ring two: gap of two cells in the top middle.
		[Vector2(2, 2), Vector2(4, 2)],
		[Vector2(2, 2), Vector2(2, 8)],
		[Vector2(2, 8), Vector2(5, 8)],
		# The goal room: two cells square, open along the bottom.
		[Vector2(4, 4), Vector2(5, 4)],
		[Vector2(4, 4), Vector2(4, 6)],
		# Chicanes: one-cell stubs into the corridors, alternating sides.
		[Vector2(0, 4), Vector2(1, 4)],
		[Vector2(2, 6), Vector2(1, 6)],
		[Vector2(3, 0), Vector2(3, 1)],
		[Vector2(3, 10), Vector2(3, 9)],
		[Vector2(2, 5), Vector2(3, 5)],
		[Vector2(4, 8), Vector2(4, 7)],
	]
	for wall: Array in left_half:
		history.commit(WallAction.new(level, wall[0] * CELL, wall[1] * CELL, axis))
	var starts := BoardItems.empty_set()
	starts["starts"] = _centres([Vector2i(0, 0), Vector2i(0, 9)])
	history.commit(AddItemsAction.new(level, Mirror.mirror_set(starts, axis), "Add ball start"))
	var holes := BoardItems.empty_set()
	holes["holes"] = _centres([Vector2i(1, 2), Vector2i(0, 8), Vector2i(3, 3)])
	history.commit(AddItemsAction.new(level, Mirror.mirror_set(holes, axis), "Add black hole"))
	history.commit(
		SetPropertiesAction.new(level, {"goal_radius": MazeGenerator.GOAL_RADIUS}, "Goal ring")
	)
	return refuse_wall_in_goal_ring(level)


## First Roll: one ball and a corridor that folds back twice (right, down, left, down,
## right): each tilt rolls the ball to the next turn, and the goal lies at the corridor's
## dead end, so a ball resting there is in. The first board: it teaches tilting.
static func make_first_roll() -> BoardLevel:
	return _fold(
		"first_roll",
		"First Roll",
		"One ball. Tilt it right, down, left, down and right again: it rests in the goal.",
		Vector2i(5, 3),
		[Vector2i(0, 0)]
	)


## Two Together: the same folding corridor, one fold longer, with two balls that roll as a
## pair; the dead end holds both, one behind the other, inside the goal.
static func make_two_together() -> BoardLevel:
	return _fold(
		"two_together",
		"Two Together",
		"Two balls roll one behind the other: bring both into the goal at the corridor's end.",
		Vector2i(6, 4),
		[Vector2i(0, 0), Vector2i(1, 0)]
	)


# A one-cell corridor folding back at every row (it turns down at the right end of the even
# rows and the left end of the odd ones), balls starting in `start_cells`, and a small goal
# at the corridor's dead end: a ball there, or two in a row, rest with their centres in it.
static func _fold(
	id: String, title: String, blurb: String, cells: Vector2i, start_cells: Array
) -> BoardLevel:
	var history := ActionHistory.new()
	var level := maze_base(history, id, title, blurb, cells)
	var far := Vector2(cells) * CELL
	var walls: Array = [
		[Vector2.ZERO, Vector2(far.x, 0.0)],
		[Vector2(far.x, 0.0), far],
		[far, Vector2(0.0, far.y)],
		[Vector2(0.0, far.y), Vector2.ZERO],
	]
	for row in range(1, cells.y):
		var y := row * CELL
		# after an even row the way down is at the right end, after an odd one at the left
		if row % 2 == 1:
			walls.append([Vector2(0.0, y), Vector2(far.x - CELL, y)])
		else:
			walls.append([Vector2(CELL, y), Vector2(far.x, y)])
	for wall: Array in walls:
		history.commit(WallAction.new(level, wall[0], wall[1]))
	var starts := BoardItems.empty_set()
	starts["starts"] = _centres(start_cells)
	history.commit(AddItemsAction.new(level, starts, "Add ball start"))
	# The last row runs toward the side its fold does not open on: the dead end is there.
	var last := cells.y - 1
	var dead_end_right := last % 2 == 0
	var face := far.x - level.wall_width * 0.5 if dead_end_right else level.wall_width * 0.5
	var inward := -1.0 if dead_end_right else 1.0
	# the goal fills the dead end's last square of corridor: a ball resting at the end lies a
	# radius from the wall's face, a second one behind it two radii further, both inside
	var goal := Vector2(face + inward * level.path_width * 0.5, (last + 0.5) * CELL)
	history.commit(
		SetPropertiesAction.new(
			level, {"goal_center": goal, "goal_radius": FOLD_GOAL_RADIUS}, "Goal at the end"
		)
	)
	return level


## `level`, or null (with an error naming the wall) when a wall crosses its goal ring: a
## ball on such a wall could never roll all the way in, so no built maze may have one.
static func refuse_wall_in_goal_ring(level: BoardLevel) -> BoardLevel:
	var crossing := MazeGenerator.wall_in_goal_ring(level)
	if crossing < 0:
		return level
	push_error(
		(
			"%s: the wall from %s to %s crosses the goal ring."
			% [level.board_id, level.walls[crossing * 2], level.walls[crossing * 2 + 1]]
		)
	)
	return null


## A fresh maze board: the tutorial's corridor and wall sizes, goal in the middle.
static func maze_base(
	history: ActionHistory, id: String, title: String, blurb: String, cells: Vector2i
) -> BoardLevel:
	var level := BoardLevel.new()
	var settings := NewBoard.maze_settings(id, title, blurb, cells)
	history.commit(SetPropertiesAction.new(level, settings, "Board settings"))
	return level


# Depth-first carving from the goal room (its top left cell `room`): a perfect maze over
# every cell.
static func _carve(
	rng: RandomNumberGenerator,
	cols: int,
	rows: int,
	room: Vector2i,
	horizontal: Array,
	vertical: Array
) -> void:
	var seen := {}
	for cell: Vector2i in [room, room + Vector2i.RIGHT, room + Vector2i.DOWN, room + Vector2i.ONE]:
		seen[cell] = true
	var stack: Array[Vector2i] = [room]
	var steps: Array[Vector2i] = [Vector2i.LEFT, Vector2i.RIGHT, Vector2i.UP, Vector2i.DOWN]
	while not stack.is_empty():
		var here: Vector2i = stack.back()
		var options: Array[Vector2i] = []
		for step in steps:
			var next := here + step
			if (
				next.x >= 0
				and next.y >= 0
				and next.x < cols
				and next.y < rows
				and not seen.has(next)
			):
				options.append(next)
		if options.is_empty():
			stack.pop_back()
			continue
		var next: Vector2i = options[rng.randi_range(0, options.size() - 1)]
		if next.x != here.x:
			vertical[maxi(next.x, here.x)][here.y] = false
		else:
			horizontal[maxi(next.y, here.y)][here.x] = false
		seen[next] = true
		stack.append(next)


# Runs of wall flags along each grid line, joined into as few walls as possible.
static func _merged_walls(horizontal: Array, vertical: Array, cols: int, rows: int) -> Array:
	var walls := []
	for r in rows + 1:
		var start := -1
		for c in cols + 1:
			var on: bool = c < cols and horizontal[r][c]
			if on and start < 0:
				start = c
			elif not on and start >= 0:
				walls.append([Vector2(start, r) * CELL, Vector2(c, r) * CELL])
				start = -1
	for c in cols + 1:
		var start := -1
		for r in rows + 1:
			var on: bool = r < rows and vertical[c][r]
			if on and start < 0:
				start = r
			elif not on and start >= 0:
				walls.append([Vector2(c, start) * CELL, Vector2(c, r) * CELL])
				start = -1
	return walls


# Cells closed on three sides, away from the corners where balls start.
static func _dead_ends(horizontal: Array, vertical: Array, cols: int, rows: int) -> Array[Vector2i]:
	var found: Array[Vector2i] = []
	for r in rows:
		for c in cols:
			var closed := int(horizontal[r][c]) + int(horizontal[r + 1][c])
			closed += int(vertical[c][r]) + int(vertical[c + 1][r])
			var corner := (c <= 1 or c >= cols - 2) and (r <= 1 or r >= rows - 2)
			if closed == 3 and not corner:
				found.append(Vector2i(c, r))
	return found


static func _grid(lines: int, cells: int) -> Array:
	var grid := []
	for i in lines:
		var line := []
		line.resize(cells)
		line.fill(true)
		grid.append(line)
	return grid


static func _centres(cells: Array) -> PackedVector2Array:
	var points := PackedVector2Array()
	for cell: Vector2i in cells:
		points.append((Vector2(cell) + Vector2(0.5, 0.5)) * CELL)
	return points
