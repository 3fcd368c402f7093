@tool
extends BoardAction
## Replaces a maze board's layout with a generated one (MazeGenerator) in one undo step:
## size, grid, walls, starts, goal and holes become the generated maze's; the board's id,
## name, description and tuning stay. Medal times belonged to the old layout, so they go.
## The maze is generated once, when the action is made, so redo lands the same board.

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

## Why no maze could be made ("" when the action is ready to commit).
var error := ""
## Black holes the generator placed (may be fewer than asked for).
var holes_placed := 0
var _values := {}


func _init(on_level: BoardLevel, settings: MazeGenSettings) -> void:
	super(on_level)
	if on_level == null or not on_level.is_maze():
		error = "The maze generator works on maze boards only."
		return
	var made := MazeGenerator.generate(settings)
	if made.has("error"):
		error = made["error"]
		return
	var generated: BoardLevel = made["level"]
	holes_placed = made["holes_placed"]
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
