@tool
extends "res://addons/board_editor/tools/board_tool.gd"
## Click to place one thing: a pin, a black hole, a ball start, a windmill (all mirrored in
## mirror mode; a mirrored windmill turns the other way), or the goal (moves it). Snapped to
## the grid, or to maze cells on a maze.

const AddItemsAction := preload("res://addons/board_editor/actions/add_items_action.gd")
const SetPropertiesAction := preload("res://addons/board_editor/actions/set_properties_action.gd")
const PlacementCheck := preload("res://addons/board_editor/core/placement_check.gd")

## The row of what this tool places (ItemKind.placed_by_click): one item per click, or for
## a SINGLE kind (the goal) the click moves it.
var kind: ItemKind
var _check := PlacementCheck.new()


## A tool that places items of the editor's pick `places` (an ItemKind.Pick value).
func _init(on_session: BoardEditSession, places: int) -> void:
	super(on_session)
	kind = ItemKinds.of_pick(places)


func press(at: Vector2, _event: InputEventMouseButton) -> bool:
	var spot := _spot(at)
	if kind.shape == ItemKind.Shape.SINGLE:
		var moved := "Move %s" % kind.singular.to_lower()
		session.commit(SetPropertiesAction.new(level(), {kind.field: spot}, moved))
		return true
	var data := _data_at(spot)
	var action := AddItemsAction.new(
		level(), session.mirrored(data), "Add %s" % kind.singular.to_lower()
	)
	session.commit(action)
	session.select(action.added)
	return true


func draw(canvas: Control, to_screen: Transform2D) -> void:
	var spot := _spot(hover)
	var outline := ItemOutline.of_value(kind, level(), _new_value(spot))
	var spots := PackedVector2Array([spot])
	if session.mirror_enabled and kind.shape != ItemKind.Shape.SINGLE:
		spots.append(Vector2(2.0 * session.mirror_axis() - spot.x, spot.y))
	if kind.ghost_crowds:
		OverlayDraw.ghost_points(canvas, to_screen, spots, outline.radius, level())
		return
	var color := OverlayDraw.GHOST_COLOR
	if would_add_error(spot):
		color = OverlayDraw.BLOCKED_COLOR  # a click here would give the board a problem
	# Big things (the goal, a windmill's sweep) are outlined: the board under them shows.
	for point in spots:
		OverlayDraw.circle(canvas, to_screen, point, outline.radius, color, not outline.hollow)


## True when placing here (with its mirror twin) would give the board a new error; for the
## goal, when it would land on a wall, a ball start or a black hole.
func would_add_error(spot: Vector2) -> bool:
	if kind.shape == ItemKind.Shape.SINGLE:
		return PlacementCheck.goal_blocked(level(), spot)
	return _check.adds_error(level(), session.mirrored(_data_at(spot)))


# What a click at `spot` adds (before mirroring).
func _data_at(spot: Vector2) -> Dictionary:
	var data := BoardItems.empty_set()
	var value: Variant = _new_value(spot)
	if value is Vector2:
		data[kind.set_key] = PackedVector2Array([value])
	else:
		data[kind.set_key] = [value]
	return data


func _spot(at: Vector2) -> Vector2:
	return session.snap_cell_point(at)


# What a click at `spot` places: the row's new item (a windmill), else the point.
func _new_value(spot: Vector2) -> Variant:
	return kind.creates.call(spot) if kind.creates.is_valid() else spot
