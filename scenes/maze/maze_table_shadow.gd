class_name MazeTableShadow
extends MeshInstance3D
## The board's shadow on the table under it: the outline of the tilted board's box cast
## along the sun's direction onto the table's plane, filled with a soft-edged translucent
## shade. Geometry, not a shadow map, so the whole table costs one small polygon instead of a
## screen-sized surface drawn twice (the 3D view must stay smooth on software GL).

## How dark the middle of the shadow is (0..1), and how wide its soft edge, in 3D units.
const DARKNESS := 0.16
const FEATHER := 0.16

## The shade's colour (its alpha is DARKNESS).
var colour := Color.BLACK

var _mesh := ArrayMesh.new()
var _material := StandardMaterial3D.new()


func _init() -> void:
	mesh = _mesh
	_material.shading_mode = BaseMaterial3D.SHADING_MODE_UNSHADED
	_material.transparency = BaseMaterial3D.TRANSPARENCY_ALPHA
	_material.vertex_color_use_as_albedo = true
	_material.cull_mode = BaseMaterial3D.CULL_DISABLED
	cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
	material_override = _material


## Recasts the shadow of the box corners `corners` (stage space) along `sun_direction` onto
## the plane z = `table_z`.
func cast(corners: PackedVector3Array, sun_direction: Vector3, table_z: float) -> void:
	var hull := outline(corners, sun_direction, table_z)
	_mesh.clear_surfaces()
	if hull.size() < 3:
		return
	var centre := Vector2.ZERO
	for p in hull:
		centre += p
	centre /= float(hull.size())
	var solid := Color(colour, DARKNESS)
	var clear := Color(colour, 0.0)
	var verts := PackedVector3Array()
	var colours := PackedColorArray()
	var count := hull.size()
	for i in count:
		var a := hull[i]
		var b := hull[(i + 1) % count]
		var a_out := a + (a - centre).normalized() * FEATHER
		var b_out := b + (b - centre).normalized() * FEATHER
		var inner_a := centre.lerp(a, 0.7)
		var inner_b := centre.lerp(b, 0.7)
		# the flat middle, then the ramp to the edge, then the feather beyond it
		_add(verts, colours, [centre, inner_a, inner_b], [solid, solid, solid], table_z)
		_add(
			verts,
			colours,
			[inner_a, a, b],
			[solid, solid.lerp(clear, 0.5), solid.lerp(clear, 0.5)],
			table_z
		)
		_add(verts, colours, [inner_a, b, inner_b], [solid, solid.lerp(clear, 0.5), solid], table_z)
		_add(verts, colours, [a, a_out, b_out], [solid.lerp(clear, 0.5), clear, clear], table_z)
		_add(
			verts,
			colours,
			[a, b_out, b],
			[solid.lerp(clear, 0.5), clear, solid.lerp(clear, 0.5)],
			table_z
		)
	var arrays := []
	arrays.resize(Mesh.ARRAY_MAX)
	arrays[Mesh.ARRAY_VERTEX] = verts
	arrays[Mesh.ARRAY_COLOR] = colours
	_mesh.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, arrays)


## The outline (x, y on the table) of the shadow that points `corners` cast along
## `sun_direction` onto the plane z = `table_z`: the convex hull of their projections.
## Empty when the sun does not shine down onto the table.
static func outline(
	corners: PackedVector3Array, sun_direction: Vector3, table_z: float
) -> PackedVector2Array:
	if sun_direction.z >= -0.0001:
		return PackedVector2Array()
	var cast_points := PackedVector2Array()
	for p in corners:
		var t := (table_z - p.z) / sun_direction.z
		var hit := p + sun_direction * t
		cast_points.append(Vector2(hit.x, hit.y))
	var hull := Geometry2D.convex_hull(cast_points)
	if hull.size() > 1 and hull[0] == hull[hull.size() - 1]:
		hull.remove_at(hull.size() - 1)  # convex_hull repeats its first point at the end
	return hull


static func _add(
	verts: PackedVector3Array, colours: PackedColorArray, points: Array, tints: Array, z: float
) -> void:
	for k in 3:
		var p: Vector2 = points[k]
		verts.append(Vector3(p.x, p.y, z))
		var tint: Color = tints[k]
		colours.append(tint)
