class_name MazeFloorArrows
extends MeshInstance3D
## A maze board's floor arrows (FloorArrowSpec) in 3D: flat paint a hair above the floor,
## one mesh for all of them, in the board's mesh units (MazeMeshes.to_local). A child of
## the board, so it tilts with it; no physics, balls roll over it.

## How far above the floor the paint lies (px): enough to never flicker into it.
const LIFT_PX := 0.3


func _init() -> void:
	cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF


## Paints the arrows of `level` (none: no mesh).
func build(level: BoardLevel) -> void:
	mesh = arrows_mesh(level)
	if mesh != null:
		var paint := StandardMaterial3D.new()
		paint.albedo_color = FloorArrowKind.PAINT
		paint.roughness = 0.9
		paint.specular_mode = BaseMaterial3D.SPECULAR_DISABLED
		mesh.surface_set_material(0, paint)


## Every arrow of `level` as flat triangles facing up, or null when it has none.
static func arrows_mesh(level: BoardLevel) -> ArrayMesh:
	if level.floor_arrows.is_empty():
		return null
	var paint := SurfaceTool.new()
	paint.begin(Mesh.PRIMITIVE_TRIANGLES)
	for arrow in level.floor_arrows:
		if arrow == null:
			continue
		var outline := arrow.polygon()
		var corners := Geometry2D.triangulate_polygon(outline)
		for k in range(0, corners.size() - 2, 3):
			var a := MazeMeshes.to_local(level.size, outline[corners[k]], LIFT_PX)
			var b := MazeMeshes.to_local(level.size, outline[corners[k + 1]], LIFT_PX)
			var c := MazeMeshes.to_local(level.size, outline[corners[k + 2]], LIFT_PX)
			# Godot's front faces wind clockwise as seen: seen from above (+z), here.
			if (b - a).cross(c - a).z > 0.0:
				var swap := b
				b = c
				c = swap
			for corner: Vector3 in [a, b, c]:
				paint.set_normal(Vector3.BACK)
				paint.add_vertex(corner)
	return paint.commit()
