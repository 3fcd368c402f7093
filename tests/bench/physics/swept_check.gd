extends RefCounted
## The benchmark's own tunnel and escape counter, independent of either physics engine:
## between two snapshots a ball's centre moves along a segment; it tunnelled if that segment
## crosses a wall's core segment or passes within a pin's own radius of the pin's centre,
## and it escaped if its centre ends outside the ring (or the maze's outer box).

const CELL := 32.0

var tunnels := 0
var escapes := 0

var _pins := PackedVector2Array()
var _pin_r := 0.0
var _walls := PackedVector2Array()
var _ring := false
var _ring_r := 0.0
var _box := Rect2()
var _origin := Vector2.ZERO
var _cols := 1
var _rows := 1
var _cell_pins: Array[PackedInt32Array] = []
var _cell_walls: Array[PackedInt32Array] = []


func _init(scene: Dictionary) -> void:
	_pins = scene["pins"]
	_pin_r = scene["pin_r"]
	_walls = scene["walls"]
	_ring = scene["ring"]
	_ring_r = 500.0
	var box := Rect2(-_ring_r, -_ring_r, 2.0 * _ring_r, 2.0 * _ring_r)
	if not _ring:
		box = Rect2(Vector2.ZERO, Vector2.ZERO)
		for p: Vector2 in _walls:
			box = box.expand(p)
	_box = box
	_origin = box.position - Vector2(CELL, CELL)
	_cols = int(box.size.x / CELL) + 3
	_rows = int(box.size.y / CELL) + 3
	_cell_pins.resize(_cols * _rows)
	_cell_walls.resize(_cols * _rows)
	for c: int in _cols * _rows:
		_cell_pins[c] = PackedInt32Array()
		_cell_walls[c] = PackedInt32Array()
	for i: int in _pins.size():
		var p: Vector2 = _pins[i]
		_add_box(_cell_pins, i, p - Vector2.ONE * _pin_r, p + Vector2.ONE * _pin_r)
	for w: int in _walls.size() / 2:
		var a: Vector2 = _walls[2 * w]
		var b: Vector2 = _walls[2 * w + 1]
		_add_box(
			_cell_walls,
			w,
			Vector2(minf(a.x, b.x), minf(a.y, b.y)),
			Vector2(maxf(a.x, b.x), maxf(a.y, b.y))
		)


## Checks every ball's move from `before[i]` to `after[i]`; `skip[i]` != 0 marks a teleport.
## The move is taken as the straight line between the two frames.
func check(before: PackedVector2Array, after: PackedVector2Array, skip: PackedByteArray) -> void:
	check_paths(before, after, skip, PackedInt32Array(), PackedVector2Array())


## Like check(), but a ball's move runs through the points the engine reports it passed
## inside the step (`path_slots[k]` is the ball of `path_points[k]`, grouped by ball in
## slot order, in time order): a ball that bounced inside a step is followed round its
## bounce instead of along the chord, which can cut through a pin it never touched.
func check_paths(
	before: PackedVector2Array,
	after: PackedVector2Array,
	skip: PackedByteArray,
	path_slots: PackedInt32Array,
	path_points: PackedVector2Array
) -> void:
	var k := 0
	for i: int in after.size():
		var p1: Vector2 = after[i]
		if not p1.is_finite():
			escapes += 1
			continue
		if _ring:
			if p1.length() > _ring_r:
				escapes += 1
		elif not _box.grow(0.5).has_point(p1):
			escapes += 1
		var p0: Vector2 = before[i]
		var hit := false
		while k < path_slots.size() and path_slots[k] < i:
			k += 1
		while k < path_slots.size() and path_slots[k] == i:
			var q: Vector2 = path_points[k]
			if skip[i] == 0 and _segment_tunnels(p0, q):
				hit = true
			p0 = q
			k += 1
		if skip[i] != 0:
			continue
		if _segment_tunnels(p0, p1):
			hit = true
		if hit:
			tunnels += 1


## True when the centre's straight move p0 → p1 passes within a pin's own radius of its
## centre or crosses a wall's core segment.
func _segment_tunnels(p0: Vector2, p1: Vector2) -> bool:
	var r2: float = _pin_r * _pin_r
	var x0: int = _cx(minf(p0.x, p1.x))
	var x1: int = _cx(maxf(p0.x, p1.x))
	var y0: int = _cy(minf(p0.y, p1.y))
	var y1: int = _cy(maxf(p0.y, p1.y))
	for cy: int in range(y0, y1 + 1):
		for cx: int in range(x0, x1 + 1):
			var c: int = cy * _cols + cx
			for k: int in _cell_pins[c]:
				var q: Vector2 = _pins[k]
				if Geometry2D.get_closest_point_to_segment(q, p0, p1).distance_squared_to(q) < r2:
					return true
			for k: int in _cell_walls[c]:
				var a: Vector2 = _walls[2 * k]
				var b: Vector2 = _walls[2 * k + 1]
				if p0 != p1 and Geometry2D.segment_intersects_segment(p0, p1, a, b) != null:
					return true
	return false


func _cx(x: float) -> int:
	return clampi(int((x - _origin.x) / CELL), 0, _cols - 1)


func _cy(y: float) -> int:
	return clampi(int((y - _origin.y) / CELL), 0, _rows - 1)


func _add_box(cells: Array[PackedInt32Array], index: int, lo: Vector2, hi: Vector2) -> void:
	for cy: int in range(_cy(lo.y), _cy(hi.y) + 1):
		for cx: int in range(_cx(lo.x), _cx(hi.x) + 1):
			cells[cy * _cols + cx].append(index)
