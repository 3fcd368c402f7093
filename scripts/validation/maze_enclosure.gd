class_name MazeEnclosure
extends RefCounted
## Why ball starts cannot roll to the goal, one cause at a time: either the goal is closed in
## (every start shut out of it shares that one cause) or a group of starts is closed in
## together. Of the two sides of a closed wall the smaller one is the closed-in one: a goal
## boxed into a corner is "the goal is closed in", a start boxed into a corner is "ball start
## 3 is closed in". Each cause names the walls around the closed-in side (the walls that touch
## the free space a ball has there) and whether the board's edge closes it in too.


## The causes for the starts of `level` that `fill` (a flood without holes) finds cut off
## from the goal, leaving out the start indices in `skipped`. Each cause is
## {"goal": true when the goal is the closed-in side, "starts": the start indices it shuts
## out, "walls": the indices of the walls round the closed-in side, "edge": true when the
## board's edge closes it in too}. Empty when every start reaches the goal.
static func causes(level: BoardLevel, fill: MazeFlood, skipped: Dictionary) -> Array[Dictionary]:
	var groups := {}  # region label -> start indices
	for i in level.ball_starts.size():
		if skipped.has(i) or fill.reaches_goal(level.ball_starts[i]):
			continue
		var label := fill.region_at(level.ball_starts[i])
		if not groups.has(label):
			groups[label] = PackedInt32Array()
		var members: PackedInt32Array = groups[label]
		members.append(i)
		groups[label] = members
	var found: Array[Dictionary] = []
	if groups.is_empty():
		return found
	var goal_side := _goal_side(level, fill)
	var goal_size := _count(goal_side)
	var sizes := _region_sizes(fill)
	var shut_out := PackedInt32Array()
	var shut_out_labels: Array[int] = []
	for label: int in groups:
		var members: PackedInt32Array = groups[label]
		var size: int = sizes.get(label, 0)
		if label >= 0 and goal_size < size:
			shut_out.append_array(members)
			shut_out_labels.append(label)
			continue
		var side := _cells_of(fill, [label] as Array[int])
		if label < 0:
			for i in members:  # a start inside a wall: what buries it
				var at := fill.cell_of(level.ball_starts[i])
				if at >= 0:
					side[at] = 1
		found.append(_cause(level, fill, side, goal_side, false, members))
	if not shut_out.is_empty():
		shut_out.sort()
		var outside := _cells_of(fill, shut_out_labels)
		found.push_front(_cause(level, fill, goal_side, outside, true, shut_out))
	return found


# The cells (1) of the flood regions `labels`.
static func _cells_of(fill: MazeFlood, labels: Array[int]) -> PackedByteArray:
	var cells := PackedByteArray()
	cells.resize(fill.free.size())
	for index in fill.region.size():
		if fill.region[index] >= 0 and labels.has(fill.region[index]):
			cells[index] = 1
	return cells


# One cause: the walls and edge round the `side` cells (1 = on the closed-in side). Of the
# walls round it, those that also face `outside` (where the shut-out balls are) close it in;
# a wall with free space of the closed-in side on both hands does not (when none faces the
# outside, as behind a double wall, every wall round it is named).
static func _cause(
	level: BoardLevel,
	fill: MazeFlood,
	side: PackedByteArray,
	outside: PackedByteArray,
	goal: bool,
	starts: PackedInt32Array
) -> Dictionary:
	var rim := _rim(fill, side)
	var nearest := _nearest_wall(level, fill, rim)
	var facing := _nearest_wall(level, fill, _rim(fill, outside))
	var walls := PackedInt32Array()
	var round_it := PackedInt32Array()
	var edge := false
	for index in rim.size():
		var w := nearest[index]
		if rim[index] == 1 and w < 0:
			edge = true
		if w >= 0 and not round_it.has(w):
			round_it.append(w)
			if facing.has(w):
				walls.append(w)
	if walls.is_empty():
		walls = round_it
	walls.sort()
	return {"goal": goal, "starts": starts, "walls": walls, "edge": edge}


# Per cell: the wall nearest it when it is a `rim` cell inside some wall's grown band, else
# -1. Each rim cell belongs to its nearest wall only: a wall whose band overlaps the rim
# behind a nearer wall (a frame wall behind a box) does not close anything in.
static func _nearest_wall(
	level: BoardLevel, fill: MazeFlood, rim: PackedByteArray
) -> PackedInt32Array:
	var nearest := PackedInt32Array()
	nearest.resize(rim.size())
	nearest.fill(-1)
	var best := PackedFloat32Array()
	best.resize(rim.size())
	var grow := fill.wall_grow()
	@warning_ignore("integer_division")  # walls are pairs of points
	var wall_count := level.walls.size() / 2
	for w in wall_count:
		var a := level.walls[w * 2]
		var b := level.walls[w * 2 + 1]
		for index in fill.capsule_cells(a, b, grow):
			if rim[index] == 0:
				continue
			@warning_ignore("integer_division")  # the grid row of a cell index
			var row := index / fill.cols
			var centre := Vector2((index % fill.cols + 0.5) * fill.cell, (row + 0.5) * fill.cell)
			var gap := Geometry2D.get_closest_point_to_segment(centre, a, b).distance_to(centre)
			if nearest[index] < 0 or gap < best[index]:
				nearest[index] = w
				best[index] = gap
	return nearest


# The cells a ball's centre can reach from the goal (1), or, when none is free, the cells
# under the goal's middle (the goal is buried: what buries it is its rim).
static func _goal_side(level: BoardLevel, fill: MazeFlood) -> PackedByteArray:
	var side := PackedByteArray()
	side.resize(fill.free.size())
	var queue := PackedInt32Array()
	var centre := fill.cell_of(level.goal_center)
	for cy in fill.rows:
		for cx in fill.cols:
			var at := Vector2((cx + 0.5) * fill.cell, (cy + 0.5) * fill.cell)
			var index := cy * fill.cols + cx
			if fill.free[index] == 1 and at.distance_to(level.goal_center) < level.goal_radius:
				side[index] = 1
				queue.append(index)
	if queue.is_empty():
		if centre >= 0:
			side[centre] = 1
		return side
	var head := 0
	while head < queue.size():
		var index := queue[head]
		head += 1
		for next in _neighbours(fill, index):
			if fill.free[next] == 1 and side[next] == 0:
				side[next] = 1
				queue.append(next)
	return side


# The blocked cells beside the `side` cells (and a buried side's own cells): where the walls
# and the edge that close it in are. A side cell on the grid's border counts too.
static func _rim(fill: MazeFlood, side: PackedByteArray) -> PackedByteArray:
	var rim := PackedByteArray()
	rim.resize(side.size())
	var cols := fill.cols
	var last := side.size() - cols
	for index in side.size():
		if side[index] == 0:
			continue
		var cx := index % cols
		if fill.free[index] == 0 or cx == 0 or cx == cols - 1 or index < cols or index >= last:
			rim[index] = 1
			continue
		if fill.free[index - 1] == 0:
			rim[index - 1] = 1
		if fill.free[index + 1] == 0:
			rim[index + 1] = 1
		if fill.free[index - cols] == 0:
			rim[index - cols] = 1
		if fill.free[index + cols] == 0:
			rim[index + cols] = 1
	return rim


static func _neighbours(fill: MazeFlood, index: int) -> PackedInt32Array:
	var found := PackedInt32Array()
	var cx := index % fill.cols
	if cx > 0:
		found.append(index - 1)
	if cx < fill.cols - 1:
		found.append(index + 1)
	if index >= fill.cols:
		found.append(index - fill.cols)
	if index + fill.cols < fill.free.size():
		found.append(index + fill.cols)
	return found


static func _count(cells: PackedByteArray) -> int:
	return cells.count(1)


static func _region_sizes(fill: MazeFlood) -> Dictionary:
	var counts := PackedInt32Array()
	for label in fill.region:
		if label >= counts.size():
			counts.resize(label + 1)
		if label >= 0:
			counts[label] += 1
	var sizes := {}
	for label in counts.size():
		sizes[label] = counts[label]
	return sizes
