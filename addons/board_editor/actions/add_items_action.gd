@tool
extends BoardAction
## Adds a set of things to a board: field pins, pockets (with their stamped rim pins and
## special pin), walls, black holes, ball starts, bonus pockets (kept in role order, as
## the board file stores them) and windmills: every ItemKinds row with an item-set key, on a
## board of its game. Placing, pasting and duplicating are all this action; `added` lists the
## new items so the editor can select them.

const BoardItems := preload("res://addons/board_editor/core/board_items.gd")

## The new items after the last `do()`.
var added: Array[Vector2i] = []
var _data: Dictionary
var _name: String
# Set key -> the values to add; resources are copied once, so a redo brings back the very
# same objects.
var _values := {}


## `item_set` has the shape of BoardItems.empty_set(); positions are board pixels.
func _init(on_level: BoardLevel, item_set: Dictionary, action_name := "Add to board") -> void:
	super(on_level)
	_data = item_set
	_name = action_name
	for kind in ItemKinds.set_rows():
		var values: Array = []
		for value: Variant in BoardItems.set_values(item_set, kind):
			values.append(kind.moved_value(value, Vector2.ZERO))
		_values[kind.set_key] = values


func get_name() -> String:
	return _name


## How many things this action adds.
func size() -> int:
	return BoardItems.set_size(_data)


func _touched_fields() -> PackedStringArray:
	return BoardItems.item_fields()


func _apply() -> void:
	added.clear()
	# One copy per field, handed back at the end (ItemEdits.working).
	var work := {}
	var handles: Array = []  # [kind, handle] for each added item, in order
	for set_kind in ItemKinds.set_rows():
		var values: Array = _values[set_kind.set_key]
		var step := 2 if set_kind.shape == ItemKind.Shape.SEGMENT else 1
		for i in range(0, values.size() - step + 1, step):
			var value: Variant = values[i] if step == 1 else values.slice(i, i + step)
			var kind := _kind_of(set_kind, value)
			if kind == null or kind.game != level.kind:
				continue
			handles.append([kind, ItemEdits.append(kind, level, work, value)])
	ItemEdits.store(level, work)
	for entry: Array in handles:
		var kind: ItemKind = entry[0]
		added.append(BoardItems.make(kind.pick, ItemEdits.index_in(kind, work, entry[1])))


# The row of one set value: a bonus pocket's is its role's.
static func _kind_of(set_kind: ItemKind, value: Variant) -> ItemKind:
	if set_kind.shape != ItemKind.Shape.ROLE_SPEC:
		return set_kind
	var spec: BonusPocketSpec = value
	return ItemKinds.of_role(spec.role)
