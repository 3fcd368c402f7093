@tool
class_name FloorArrowKind
extends RefCounted
## Floor arrows (FloorArrowSpec): hints painted on a maze's floor, each a position and an
## angle. Paint only: the world builds nothing for them, balls roll over them. A designer
## places them with their own tool (Y), moves, mirrors and turns them (the angle field).

## The colour they are painted in: a soft blue that reads on the maple floor and the plain
## menu floor alike.
const PAINT := Color("4f7cac")


## The floor arrow row of ItemKinds.
static func row() -> ItemKind:
	var kind := ItemKind.make("floor_arrow", "floor_arrows", ItemKind.Shape.SPEC)
	kind.list = "floor_arrows"
	kind.id_field = "floor_arrow_ids"
	kind.game = BoardLevel.Kind.MAZE
	kind.singular = "Floor arrow"
	kind.plural = "Floor arrows"
	kind.set_key = "floor_arrows"
	kind.spec_values = PackedStringArray(["position", "angle"])
	kind.max_items = 200
	var angles := FloorArrowSpec.ANGLE_RANGE
	kind.file_fields = {"x": ["coord"], "y": ["coord"], "angle": ["float", angles.x, angles.y]}
	kind.optional_file_fields = {"id": ["int", 1, ItemKind.MAX_ID]}
	kind.reads = _read
	kind.writes = _write
	kind.turns = _turn
	kind.layer = "Floor arrows"
	kind.paint_layer = "FLOOR_ARROWS"
	kind.paints = paint
	kind.placed_by_click = true
	kind.creates = func(at: Vector2) -> FloorArrowSpec: return FloorArrowSpec.create(at, 0.0)
	kind.tool_key = KEY_Y
	kind.tool_tip = "Click to paint an arrow on the floor (turn it with its angle field)."
	kind.outlines = _circle
	kind.properties = _fields
	kind.edits = _set_angle
	return kind


## Paints arrow `index` of `level` on `canvas` (board pixels): the 2D board's drawing.
static func paint(canvas: CanvasItem, level: BoardLevel, index: int) -> void:
	canvas.draw_colored_polygon(level.floor_arrows[index].polygon(), PAINT)


static func _read(level: BoardLevel, lines: Array) -> Array:
	var arrows: Array[FloorArrowSpec] = []
	for line: Dictionary in lines:
		var at := Vector2(LineText.float_of(line["x"]), LineText.float_of(line["y"]))
		arrows.append(FloorArrowSpec.create(at, LineText.float_of(line["angle"])))
	level.floor_arrows = arrows
	return lines


static func _write(level: BoardLevel, index: int) -> String:
	var arrow := level.floor_arrows[index]
	var x := LineText.number(arrow.position.x)
	var y := LineText.number(arrow.position.y)
	return '"x": %s, "y": %s, "angle": %s' % [x, y, LineText.number(arrow.angle)]


# A mirror image points the other way across the vertical axis: right becomes left.
static func _turn(arrow: FloorArrowSpec) -> void:
	arrow.angle = wrapf(180.0 - arrow.angle, -180.0, 180.0)


# Picked within the circle round its tips.
static func _circle(_level: BoardLevel, arrow: FloorArrowSpec) -> ItemOutline:
	return ItemOutline.circle(arrow.position, FloorArrowSpec.LENGTH * 0.5)


static func _fields(level: BoardLevel, index: int) -> Dictionary:
	var arrow := level.floor_arrows[index]
	return {"x": arrow.position.x, "y": arrow.position.y, "angle": arrow.angle}


static func _set_angle(level: BoardLevel, index: int, key: String, value: float) -> void:
	if key == "angle":
		level.floor_arrows[index].angle = wrapf(value, -180.0, 180.0)
