@tool
extends "res://addons/board_editor/actions/add_items_action.gd"
## Stamps a pin pattern (row, staggered lattice, arc, circle) from PinPatterns, sized by a
## pin count and the spacing between neighbouring pins, and mirrored when asked.
##
## Settings: kind, count (pins per row / on the arc / round the circle), spacing (px
## between neighbours), rows (lattice), radius (arc). `origin` is the row's or lattice's
## centre, and the centre of the arc's or circle's circle (an arc bows upwards from it).

const Mirror := preload("res://addons/board_editor/core/mirror.gd")

## Pattern kinds the tool offers.
const KINDS: Array[String] = ["row", "lattice", "arc", "circle"]


## `mirror_axis` is the x to mirror across, or NAN for no mirror.
func _init(
	on_level: BoardLevel, settings: Dictionary, origin: Vector2, mirror_axis: float = NAN
) -> void:
	var data := BoardItems.empty_set()
	data["pins"] = points_for(settings, origin)
	if not is_nan(mirror_axis):
		data = Mirror.mirror_set(data, mirror_axis)
	super(on_level, data, "Add %s of pins" % str(settings.get("kind", "row")))


## The pin centres a pattern puts down around `origin` (empty for bad settings, with an
## error naming the problem).
static func points_for(settings: Dictionary, origin: Vector2) -> PackedVector2Array:
	var kind := str(settings.get("kind", "row"))
	var count: int = settings.get("count", 0)
	var spacing: float = settings.get("spacing", 0.0)
	if count < 1 or spacing <= 0.0 or not KINDS.has(kind):
		push_error(
			(
				"Pin pattern: need a known kind, count >= 1 and spacing > 0 (got %s, %d, %.1f)."
				% [kind, count, spacing]
			)
		)
		return PackedVector2Array()
	match kind:
		"row":
			var half := Vector2((count - 1) * spacing * 0.5, 0)
			return PinPatterns.row(origin - half, origin + half, count)
		"lattice":
			var wanted_rows: int = settings.get("rows", 1)
			var rows := maxi(wanted_rows, 1)
			# Equilateral stagger: every pin is `spacing` from its six neighbours.
			var pitch := Vector2(spacing, spacing * sqrt(3.0) * 0.5)
			var extent := Vector2((count - 1) * pitch.x, (rows - 1) * pitch.y)
			return PinPatterns.staggered_lattice(Rect2(origin - extent * 0.5, extent), pitch)
		"arc":
			var wanted_radius: float = settings.get("radius", spacing)
			var radius := maxf(wanted_radius, spacing * 0.5)
			var step := rad_to_deg(2.0 * asin(minf(spacing / (2.0 * radius), 1.0)))
			var span := step * (count - 1)
			return PinPatterns.arc(origin, radius, -90.0 - span * 0.5, -90.0 + span * 0.5, count)
		_:
			if count < 2:
				return PinPatterns.circle(origin, 0.0, 1)
			var around := spacing / (2.0 * sin(PI / count))
			return PinPatterns.circle(origin, around, count, -90.0)
