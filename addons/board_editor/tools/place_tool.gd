@tool
extends "res://addons/board_editor/tools/board_tool.gd"
## Click to place one thing: a pin, a black hole, a ball start, a windmill (all mirrored in
## mirror mode; a mirrored windmill turns the other way), or the goal (moves it). Snapped to
## the grid, or to maze cells on a maze.

const AddItemsAction := preload("res://addons/board_editor/actions/add_items_action.gd")
const SetPropertiesAction := preload("res://addons/board_editor/actions/set_properties_action.gd")
const PlacementCheck := preload("res://addons/board_editor/core/placement_check.gd")

## What this tool places: Items.Kind.PIN, HOLE, START, WINDMILL or GOAL.
var kind: int
var _check := PlacementCheck.new()


func _init(on_session: Session, places: int) -> void:
	super(on_session)
	kind = places


func press(at: Vector2, _event: InputEventMouseButton) -> bool:
	var spot := _spot(at)
	if kind == Items.Kind.GOAL:
		session.commit(SetPropertiesAction.new(level(), {"goal_center": spot}, "Move goal"))
		return true
	var data := _data_at(spot)
	var names := {
		Items.Kind.PIN: "Add pin",
		Items.Kind.HOLE: "Add black hole",
		Items.Kind.WINDMILL: "Add windmill",
	}
	var action := AddItemsAction.new(
		level(), session.mirrored(data), str(names.get(kind, "Add ball start"))
	)
	session.commit(action)
	session.select(action.added)
	return true


func draw(canvas: Control, to_screen: Transform2D) -> void:
	var spot := _spot(hover)
	var radius := level().pin_radius
	match kind:
		Items.Kind.HOLE:
			radius = level().hole_radius
		Items.Kind.START:
			radius = level().ball_radius
		Items.Kind.GOAL:
			radius = level().goal_radius
	var spots := PackedVector2Array([spot])
	if session.mirror_enabled and kind != Items.Kind.GOAL:
		spots.append(Vector2(2.0 * session.mirror_axis() - spot.x, spot.y))
	if kind == Items.Kind.WINDMILL:
		radius = new_windmill(spot).sweep_radius()
	if kind == Items.Kind.PIN:
		Draw.ghost_points(canvas, to_screen, spots, radius, level())
		return
	var color := Draw.GHOST_COLOR
	if would_add_error(spot):
		color = Draw.BLOCKED_COLOR  # a click here would give the board a problem
	# The goal and a windmill's sweep are big: an outline keeps the board under them visible.
	var filled := kind != Items.Kind.GOAL and kind != Items.Kind.WINDMILL
	for point in spots:
		Draw.circle(canvas, to_screen, point, radius, color, filled)


## True when placing here (with its mirror twin) would give the board a new error; for the
## goal, when it would land on a wall, a ball start or a black hole.
func would_add_error(spot: Vector2) -> bool:
	if kind == Items.Kind.GOAL:
		return PlacementCheck.goal_blocked(level(), spot)
	return _check.adds_error(level(), session.mirrored(_data_at(spot)))


## The windmill this tool places at `at`: four blades turning clockwise (WindmillSpec's
## defaults; the property panel changes them).
static func new_windmill(at: Vector2) -> WindmillSpec:
	return WindmillSpec.driven(
		at, WindmillSpec.DEFAULT_BLADES, WindmillSpec.DEFAULT_LENGTH, WindmillSpec.DEFAULT_SPEED
	)


# What a click at `spot` adds (before mirroring).
func _data_at(spot: Vector2) -> Dictionary:
	var data := Items.empty_set()
	if kind == Items.Kind.WINDMILL:
		data["windmills"] = [new_windmill(spot)]
	else:
		var key := {Items.Kind.PIN: "pins", Items.Kind.HOLE: "holes", Items.Kind.START: "starts"}
		data[key[kind]] = PackedVector2Array([spot])
	return data


func _spot(at: Vector2) -> Vector2:
	return session.snap_point(at) if kind == Items.Kind.PIN else session.snap_cell_point(at)
