class_name MazeMeshes
extends RefCounted
## Builds the maze board's 3D meshes from its level data: every wall of the board as one
## extruded stadium (a box with a round cap at each end, the physics' capsule) in a single
## ArrayMesh, the raised frame round the board, and the holes as dark tubes sunk into the
## floor. Board pixels go in; mesh units come out (one unit = 100 board pixels), in the
## board's local frame: x right, y up the screen, z out of the floor toward the player.
## Every triangle is wound from its normals (Godot draws clockwise triangles as the front), so
## the builders only list corners in order round each face.

## One mesh unit in board pixels is 1 / UNITS_PER_PX.
const UNITS_PER_PX := 0.01
## Segments on each half of a round wall cap, and round a hole.
const CAP_SEGMENTS := 6
const HOLE_SEGMENTS := 24
## Share of the wall height that the soft top edge (a chamfer) takes.
const BEVEL_SHARE := 0.3


## A board point (pixels, y down) at `height_px` above the floor, in mesh units.
static func to_local(board_size: Vector2, p: Vector2, height_px: float = 0.0) -> Vector3:
	return Vector3(
		(p.x - board_size.x * 0.5) * UNITS_PER_PX,
		(board_size.y * 0.5 - p.y) * UNITS_PER_PX,
		height_px * UNITS_PER_PX
	)


## All `walls` (pairs of ends, board pixels) as raised stadiums `width` wide and `height`
## tall, one surface, each rounded end in `cap_segments` pieces, their top edges chamfered
## (`bevelled`). Square ends without a chamfer (1, false) are Low graphics' cheaper walls.
## Null when there are no walls.
static func walls(
	board_size: Vector2,
	ends: PackedVector2Array,
	width: float,
	height: float,
	cap_segments := CAP_SEGMENTS,
	bevelled := true
) -> ArrayMesh:
	if ends.size() < 2:
		return null
	var st := SurfaceTool.new()
	st.begin(Mesh.PRIMITIVE_TRIANGLES)
	var bevel := minf(width * 0.5, height) * BEVEL_SHARE if bevelled else 0.0
	for i in range(0, ends.size() - 1, 2):
		var outline := _stadium(ends[i], ends[i + 1], width * 0.5, maxi(cap_segments, 1))
		_extrude(st, board_size, outline, height, bevel)
	st.index()  # shared corners once: software GL pays per vertex
	return st.commit()


## The frame round the board: `margin` wide, its top `height` above the floor, its outside
## dropping `depth` below the floor, open inside (the floor shows through).
static func frame(board_size: Vector2, margin: float, height: float, depth: float) -> ArrayMesh:
	var st := SurfaceTool.new()
	st.begin(Mesh.PRIMITIVE_TRIANGLES)
	var inner := _rect(board_size, 0.0)
	var outer := _rect(board_size, margin)
	var bevel := minf(margin * 0.5, height) * BEVEL_SHARE
	for i in 4:
		var j := (i + 1) % 4
		var out_normal := _edge_normal(outer[i], outer[j])
		# outside face, from the bottom up to the chamfer
		_quad(
			st,
			[
				to_local(board_size, outer[i], -depth),
				to_local(board_size, outer[j], -depth),
				to_local(board_size, outer[j], height - bevel),
				to_local(board_size, outer[i], height - bevel),
			],
			out_normal
		)
		# the chamfer, the flat top, and the inside face down to the floor
		var in_i := outer[i] - _flat(out_normal) * bevel
		var in_j := outer[j] - _flat(out_normal) * bevel
		_quad(
			st,
			[
				to_local(board_size, outer[i], height - bevel),
				to_local(board_size, outer[j], height - bevel),
				to_local(board_size, in_j, height),
				to_local(board_size, in_i, height),
			],
			(out_normal + Vector3.BACK).normalized()
		)
		_quad(
			st,
			[
				to_local(board_size, in_i, height),
				to_local(board_size, in_j, height),
				to_local(board_size, inner[j], height),
				to_local(board_size, inner[i], height),
			],
			Vector3.BACK
		)
		_quad(
			st,
			[
				to_local(board_size, inner[i], height),
				to_local(board_size, inner[j], height),
				to_local(board_size, inner[j], 0.0),
				to_local(board_size, inner[i], 0.0),
			],
			-out_normal
		)
	# the underside, so the board's shadow on the table is whole
	_quad(
		st,
		[
			to_local(board_size, outer[3], -depth),
			to_local(board_size, outer[2], -depth),
			to_local(board_size, outer[1], -depth),
			to_local(board_size, outer[0], -depth),
		],
		Vector3.FORWARD
	)
	return st.commit()


## Every hole as a tube `depth` deep with a floor of its own: the inside wall of each tube
## in surface 0, its vertex colours fading from `rim` at the top to black at the bottom (the
## depth reads even in shade), the bottoms in surface 1. Null for none.
static func holes(
	board_size: Vector2, centres: PackedVector2Array, radius: float, depth: float, rim: Color
) -> ArrayMesh:
	if centres.is_empty():
		return null
	var tube := SurfaceTool.new()
	tube.begin(Mesh.PRIMITIVE_TRIANGLES)
	var bottom := SurfaceTool.new()
	bottom.begin(Mesh.PRIMITIVE_TRIANGLES)
	for c in centres:
		for k in HOLE_SEGMENTS:
			var a0 := TAU * float(k) / HOLE_SEGMENTS
			var a1 := TAU * float(k + 1) / HOLE_SEGMENTS
			var p0 := c + Vector2(cos(a0), sin(a0)) * radius
			var p1 := c + Vector2(cos(a1), sin(a1)) * radius
			# seen from the tube's axis, so its normals point inward
			var n0 := -_flat_normal(Vector2(cos(a0), sin(a0)))
			var n1 := -_flat_normal(Vector2(cos(a1), sin(a1)))
			var top0 := to_local(board_size, p0, 0.0)
			var top1 := to_local(board_size, p1, 0.0)
			var low0 := to_local(board_size, p0, -depth)
			var low1 := to_local(board_size, p1, -depth)
			var dark := Color.BLACK
			_tri(tube, [top0, low1, top1], [n0, n1, n1], [rim, dark, rim])
			_tri(tube, [top0, low0, low1], [n0, n0, n1], [rim, dark, dark])
			var mid := to_local(board_size, c, -depth)
			_tri(bottom, [mid, low0, low1], [Vector3.BACK, Vector3.BACK, Vector3.BACK])
	var mesh: ArrayMesh = tube.commit()
	return bottom.commit(mesh)


# The outline of a capsule from `a` to `b` with radius `r`, in order round it, as points and
# their outward directions (board pixels).
static func _stadium(a: Vector2, b: Vector2, r: float, segments: int) -> Array[PackedVector2Array]:
	var along := b - a
	var dir := along.normalized() if along.length() > 0.001 else Vector2.RIGHT
	var base := dir.angle()
	var points := PackedVector2Array()
	var normals := PackedVector2Array()
	for end in 2:
		var centre := b if end == 0 else a
		var start := base - PI * 0.5 + PI * float(end)
		for k in segments + 1:
			var angle := start + PI * float(k) / float(segments)
			var n := Vector2(cos(angle), sin(angle))
			points.append(centre + n * r)
			normals.append(n)
	return [points, normals]


# Walls of the outline up to the chamfer, the chamfer, then the flat top as a fan.
static func _extrude(
	st: SurfaceTool, size: Vector2, outline: Array[PackedVector2Array], h: float, bevel: float
) -> void:
	var points := outline[0]
	var normals := outline[1]
	var count := points.size()
	var centre := Vector2.ZERO
	for p in points:
		centre += p
	centre /= float(count)
	for i in count:
		var j := (i + 1) % count
		var ni := _flat_normal(normals[i])
		var nj := _flat_normal(normals[j])
		var ti := points[i] - normals[i] * bevel
		var tj := points[j] - normals[j] * bevel
		var lo_i := to_local(size, points[i], 0.0)
		var lo_j := to_local(size, points[j], 0.0)
		var mid_i := to_local(size, points[i], h - bevel)
		var mid_j := to_local(size, points[j], h - bevel)
		var top_i := to_local(size, ti, h)
		var top_j := to_local(size, tj, h)
		_tri(st, [lo_i, mid_j, lo_j], [ni, nj, nj])
		_tri(st, [lo_i, mid_i, mid_j], [ni, ni, nj])
		if bevel > 0.0:  # the chamfer; without it the side meets the top's edge
			var bi := (ni + Vector3.BACK).normalized()
			var bj := (nj + Vector3.BACK).normalized()
			_tri(st, [mid_i, top_j, mid_j], [bi, Vector3.BACK, bj])
			_tri(st, [mid_i, top_i, top_j], [bi, Vector3.BACK, Vector3.BACK])
		var c := to_local(size, centre, h)
		_tri(st, [c, top_j, top_i], [Vector3.BACK, Vector3.BACK, Vector3.BACK])


# The four corners of the board grown by `margin`, counter-clockwise on screen.
static func _rect(size: Vector2, margin: float) -> PackedVector2Array:
	return PackedVector2Array(
		[
			Vector2(-margin, -margin),
			Vector2(-margin, size.y + margin),
			Vector2(size.x + margin, size.y + margin),
			Vector2(size.x + margin, -margin),
		]
	)


# The outward normal (mesh space) of an edge of a counter-clockwise-on-screen outline.
static func _edge_normal(a: Vector2, b: Vector2) -> Vector3:
	var d := (b - a).normalized()
	return _flat_normal(Vector2(-d.y, d.x))


# A board direction (y down) as a mesh-space normal in the floor's plane.
static func _flat_normal(d: Vector2) -> Vector3:
	return Vector3(d.x, -d.y, 0.0)


# A mesh-space normal in the floor's plane back as a board direction.
static func _flat(n: Vector3) -> Vector2:
	return Vector2(n.x, -n.y)


static func _quad(st: SurfaceTool, corners: Array, normal: Vector3) -> void:
	_tri(st, [corners[0], corners[2], corners[1]], [normal, normal, normal])
	_tri(st, [corners[0], corners[3], corners[2]], [normal, normal, normal])


# One triangle, wound so that the side its normals point to is the front: Godot's front
# faces are clockwise, so the right-hand cross product points away from the front.
static func _tri(st: SurfaceTool, corners: Array, normals: Array, colours: Array = []) -> void:
	var a: Vector3 = corners[0]
	var b: Vector3 = corners[1]
	var c: Vector3 = corners[2]
	var facing: Vector3 = normals[0] + normals[1] + normals[2]
	if (b - a).cross(c - a).dot(facing) > 0.0:
		corners = [a, c, b]
		normals = [normals[0], normals[2], normals[1]]
		if not colours.is_empty():
			colours = [colours[0], colours[2], colours[1]]
	for k in 3:
		if not colours.is_empty():
			var colour: Color = colours[k]
			st.set_color(colour)
		var normal: Vector3 = normals[k]
		var corner: Vector3 = corners[k]
		st.set_normal(normal)
		st.add_vertex(corner)
