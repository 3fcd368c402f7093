@tool
class_name PocketSpec
extends Resource
## One pachinko pocket: a cup of rim pins with a special pin at its bottom. A ball that
## touches the special pin is caught and pays out.

## Centre of the pocket's mouth (the opening at the top), in board pixels.
@export var position: Vector2 = Vector2.ZERO:
	set(value):
		position = value
		emit_changed()
## Inside width of the mouth, in pixels.
@export var width: float = 0.0:
	set(value):
		width = value
		emit_changed()
## Distance from the mouth down to the special pin's centre, in pixels.
@export var depth: float = 0.0:
	set(value):
		depth = value
		emit_changed()
## Balls paid into the cup when a ball is caught here.
@export var payout: int = 0:
	set(value):
		payout = value
		emit_changed()


## A pocket with the given shape (a convenience for code and tests).
static func create(at: Vector2, mouth_width: float, pocket_depth: float, pays: int) -> PocketSpec:
	var spec := PocketSpec.new()
	spec.position = at
	spec.width = mouth_width
	spec.depth = pocket_depth
	spec.payout = pays
	return spec
