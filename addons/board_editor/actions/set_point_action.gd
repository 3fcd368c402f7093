@tool
extends BoardAction
## Puts one stored point of the board somewhere exact: a pin, a wall end, a black hole, a
## ball start (the property panel's x / y fields). Pockets and the goal move with
## MoveItemsAction, since a pocket takes its rim pins along.

var _field: String
var _index: int
var _to: Vector2
var _name: String


## Sets `field[index]` (a packed point array of the board) to `to`.
func _init(
	on_level: BoardLevel, field: String, index: int, to: Vector2, action_name := "Set position"
) -> void:
	super(on_level)
	_field = field
	_index = index
	_to = to
	_name = action_name


func get_name() -> String:
	return _name


## Re-applies the action with the point at `to` (a live handle drag).
func preview(to: Vector2) -> void:
	if is_applied():
		undo()
	_to = to
	do()


## Where the point goes.
func target() -> Vector2:
	return _to


func _touched_fields() -> PackedStringArray:
	return PackedStringArray([_field]) if _is_point_field(_field) else PackedStringArray()


func _apply() -> void:
	if not _is_point_field(_field):
		push_error("Set position: '%s' is not a point list of the board." % _field)
		return
	var current: PackedVector2Array = level.get(_field)
	var points := current.duplicate()
	if _index < 0 or _index >= points.size():
		push_error("Set position: %s has no point %d." % [_field, _index])
		return
	points[_index] = _to
	level.set(_field, points)


# True for a board field of points: a POINT or SEGMENT kind's (pins, walls, holes...).
static func _is_point_field(field: String) -> bool:
	var kind := ItemKinds.of_field(field)
	return (
		kind != null
		and (kind.shape == ItemKind.Shape.POINT or kind.shape == ItemKind.Shape.SEGMENT)
	)
