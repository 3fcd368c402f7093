@tool
extends BoardAction
## Replaces a maze board's layout with a generated one (MazeGenerator) in one undo step:
## size, grid, walls, starts, goal and holes become the generated maze's; the board's id,
## name, description and tuning stay. Medal times belonged to the old layout, so they go.
## The maze is generated before the action is made, so redo lands the same board.

## The fields the generated maze replaces.
const FIELDS: Array[String] = [
	"size",
	"ball_radius",
	"grid_cols",
	"grid_rows",
	"path_width",
	"wall_width",
	"walls",
	"ball_starts",
	"goal_center",
	"goal_radius",
	"holes",
	"hole_radius",
]

var _values := {}


## Replaces `on_level`'s layout with that of `generated` (a MazeGenerator result).
func _init(on_level: BoardLevel, generated: BoardLevel) -> void:
	super(on_level)
	for field in FIELDS:
		_values[field] = generated.get(field)
	_values["medal_times_easy"] = PackedFloat64Array()
	_values["medal_times_hard"] = PackedFloat64Array()


func get_name() -> String:
	return "Generate maze"


func _touched_fields() -> PackedStringArray:
	return PackedStringArray(_values.keys())


func _apply() -> void:
	for field: String in _values:
		level.set(field, _values[field])
