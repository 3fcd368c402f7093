@tool
class_name FloorArrowSpec
extends Resource
## One floor arrow of a maze board: a hint painted flat on the floor at `position`, pointing
## `angle` degrees (0 points right; y down, so a positive angle turns clockwise on screen).
## It is paint, not a piece: balls roll over it. Board files hold one per line:
## `{"floor_arrow": {"id": 1, "x": 120, "y": 80, "angle": 90}}`.

## How long an arrow is, tip to tail, and how wide its head and its shaft are (px).
const LENGTH := 30.0
const HEAD_WIDTH := 18.0
const SHAFT_WIDTH := 7.0
## How far along the arrow its head starts (share of LENGTH from the tail).
const HEAD_START := 0.55
## The angles a file may write (degrees).
const ANGLE_RANGE := Vector2(-360.0, 360.0)

## The arrow's middle, board pixels.
@export var position: Vector2 = Vector2.ZERO:
	set(value):
		position = value
		emit_changed()
## Where it points, degrees clockwise from pointing right.
@export var angle: float = 0.0:
	set(value):
		angle = value
		emit_changed()


## An arrow at `at` pointing `degrees`.
static func create(at: Vector2, degrees: float) -> FloorArrowSpec:
	var arrow := FloorArrowSpec.new()
	arrow.position = at
	arrow.angle = degrees
	return arrow


## The arrow's outline in board pixels, one polygon (tail corners, shaft, head, tip), for
## the 2D board painter and the 3D floor alike.
func polygon() -> PackedVector2Array:
	var tail := -LENGTH * 0.5
	var neck := tail + LENGTH * HEAD_START
	var shape := PackedVector2Array(
		[
			Vector2(tail, -SHAFT_WIDTH * 0.5),
			Vector2(neck, -SHAFT_WIDTH * 0.5),
			Vector2(neck, -HEAD_WIDTH * 0.5),
			Vector2(LENGTH * 0.5, 0.0),
			Vector2(neck, HEAD_WIDTH * 0.5),
			Vector2(neck, SHAFT_WIDTH * 0.5),
			Vector2(tail, SHAFT_WIDTH * 0.5),
		]
	)
	return Transform2D(deg_to_rad(angle), position) * shape
