@tool
extends "res://addons/board_editor/actions/add_items_action.gd"
## Adds a pocket: its PocketSpec and the rim pins and special pin PocketStamp makes for it
## (mirrored when asked).

const Mirror := preload("res://addons/board_editor/core/mirror.gd")


## A pocket whose mouth is centred at `mouth`; `mirror_axis` is NAN for no mirror.
func _init(
	on_level: BoardLevel,
	mouth: Vector2,
	width: float,
	depth: float,
	payout: int,
	mirror_axis: float = NAN
) -> void:
	var data := BoardItems.empty_set()
	var pockets: Array = data["pockets"]
	pockets.append(PocketSpec.create(mouth, width, depth, payout))
	if not is_nan(mirror_axis):
		data = Mirror.mirror_set(data, mirror_axis)
	super(on_level, data, "Add pocket")
