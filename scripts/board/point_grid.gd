class_name PointGrid
extends RefCounted
## A spatial hash of points: square cells `cell` px wide, each holding the indices of the
## points inside it in their order, so "which points are near this one" reads the 3×3 cells
## around it instead of every point. Points that are not finite are left out.

## The cell width, px.
var cell: float
## Cell (Vector2i) → the indices of its points (PackedInt32Array), cells in first-use order.
var buckets := {}


func _init(points: PackedVector2Array, cell_size: float) -> void:
	cell = cell_size
	for i in points.size():
		if not points[i].is_finite():
			continue
		var key := key_of(points[i])
		var bucket: PackedInt32Array = buckets.get(key, PackedInt32Array())
		bucket.append(i)
		buckets[key] = bucket


## The cell holding `point`.
func key_of(point: Vector2) -> Vector2i:
	return Vector2i(floori(point.x / cell), floori(point.y / cell))


## The indices of the points in the 3×3 cells around `point` (row by row, each cell's in
## order): every point closer than `cell` to it is among them.
func near(point: Vector2) -> PackedInt32Array:
	var found := PackedInt32Array()
	var base := key_of(point)
	for dy in range(-1, 2):
		for dx in range(-1, 2):
			var bucket: PackedInt32Array = buckets.get(base + Vector2i(dx, dy), PackedInt32Array())
			found.append_array(bucket)
	return found
