@tool
extends BoardAction
## Flips items left to right, each group about its own vertical line, in one undo step:
## pins, holes, starts and the goal land at their reflection, a wall's two ends are
## reflected, a pocket or bonus pocket moves its mouth there (its cup is symmetrical, so its
## rim pins move with it) and a windmill turns the other way. Items keep their ids.
## Flipping a selection in mirror mode is two groups: the selection about its centre, and
## the selection's twins about the reflected centre, so the board stays symmetrical.

const Items := preload("res://addons/board_editor/core/board_items.gd")
const Mirror := preload("res://addons/board_editor/core/mirror.gd")

var _groups: Array = []
var _count := 0


## `groups` is a list of [items (Array[Vector2i]), axis x (float)]: each group's items are
## reflected across the vertical line x = axis.
func _init(on_level: BoardLevel, groups: Array) -> void:
	super(on_level)
	for group: Array in groups:
		var items: Array[Vector2i] = group[0]
		var axis: float = group[1]
		_groups.append([items.duplicate(), axis])
		_count += items.size()


func get_name() -> String:
	return "Flip %d item%s left to right" % [_count, "" if _count == 1 else "s"]


func _touched_fields() -> PackedStringArray:
	return PackedStringArray(Items.POSITION_FIELDS)


func _apply() -> void:
	# Copies: packed arrays are shared by reference, and the setters must see a new value.
	var pins := level.pins.duplicate()
	var walls := level.walls.duplicate()
	var holes := level.holes.duplicate()
	var starts := level.ball_starts.duplicate()
	for group: Array in _groups:
		var axis: float = group[1]
		for item: Vector2i in group[0]:
			if not Items.is_valid(level, item):
				continue
			var shift := Mirror.reflect(Items.position_of(level, item), axis)
			shift -= Items.position_of(level, item)
			match item.x:
				Items.Kind.PIN:
					pins[item.y] = Mirror.reflect(pins[item.y], axis)
				Items.Kind.POCKET:
					level.pockets[item.y].position += shift
					for pin in Items.pocket_pins(level, item.y):
						pins[pin] += shift
				Items.Kind.WALL:
					walls[item.y * 2] = Mirror.reflect(walls[item.y * 2], axis)
					walls[item.y * 2 + 1] = Mirror.reflect(walls[item.y * 2 + 1], axis)
				Items.Kind.HOLE:
					holes[item.y] = Mirror.reflect(holes[item.y], axis)
				Items.Kind.START:
					starts[item.y] = Mirror.reflect(starts[item.y], axis)
				Items.Kind.GOAL:
					level.goal_center = Mirror.reflect(level.goal_center, axis)
				Items.Kind.BONUS:
					level.bonus_pockets[item.y].position += shift
				Items.Kind.WINDMILL:
					var wheel := level.windmills[item.y]
					wheel.position += shift
					wheel.speed = -wheel.speed
	level.pins = pins
	level.walls = walls
	level.holes = holes
	level.ball_starts = starts
