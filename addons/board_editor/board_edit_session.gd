@tool
extends RefCounted
## What the board editor is doing right now: the board, the selection, the active tool and
## its settings, snapping and mirror mode. Plain object: the plugin shows it, tests drive it.
##
## Every change goes through `commit()`, which hands the action to the committer (the
## editor's undo history in the plugin, a plain ActionHistory elsewhere).

signal edited
signal selection_changed
signal tool_changed(tool: int)
signal settings_changed

enum Tool {
	SELECT,
	PIN,
	PATTERN,
	POCKET,
	WALL,
	HOLE,
	GOAL,
	START,
	HANDLES,
	ERASE,
	CURVE,
	START_POCKET,
	ATTACKER,
	TULIP,
	WINDMILL
}

const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const Mirror := preload("res://addons/board_editor/core/mirror.gd")
const Snapping := preload("res://addons/board_editor/core/snapping.gd")
const ActionHistory := preload("res://addons/board_editor/core/action_history.gd")
const Layers := preload("res://addons/board_editor/core/layers.gd")
const PinArc := preload("res://addons/board_editor/core/pin_arc.gd")
const ItemKeys := preload("res://addons/board_editor/core/item_keys.gd")

## Tools that make sense on each kind of board.
const PACHINKO_TOOLS: Array[int] = [
	Tool.SELECT,
	Tool.PIN,
	Tool.PATTERN,
	Tool.CURVE,
	Tool.POCKET,
	Tool.HANDLES,
	Tool.ERASE,
	Tool.START_POCKET,
	Tool.ATTACKER,
	Tool.TULIP,
	Tool.WINDMILL
]
const MAZE_TOOLS: Array[int] = [
	Tool.SELECT, Tool.WALL, Tool.HOLE, Tool.GOAL, Tool.START, Tool.HANDLES, Tool.ERASE
]

## The board being edited.
var level: BoardLevel
## The selected items (see BoardItems), as they are numbered now; the session remembers
## them by their stable ids (ItemKeys), so after an edit they are the same items.
var selection: Array[Vector2i] = []
## The active tool.
var tool: int = Tool.SELECT
## Snap to the editor grid (and, on a maze, walls to the maze lattice).
var snap_enabled := true
## Editor grid pitch in pixels.
var grid_step := 10.0
## Edit both halves at once, mirrored across the board's centre line.
var mirror_enabled := false
## Pattern tool settings: kind ("row", "lattice", "arc", "circle"), count, spacing, rows,
## radius (arcs), arc_deg (arcs).
var pattern := {
	"kind": "row", "count": 7, "spacing": 30.0, "rows": 4, "radius": 120.0, "arc_deg": 120.0
}
## Peg line along a drawn curve: `count` pins end to end, or (count 0) one every `spacing` px.
var curve := {"count": 20, "spacing": 24.0}
## Settings for new pockets.
var pocket_width := 32.0
var pocket_depth := 24.0
var pocket_payout := 10
## Layers (Layers.for_kind names) the designer hid or locked.
var hidden_layers: Array[String] = []
var locked_layers: Array[String] = []
## The last copied items, relative to their centre.
var clipboard := {}
## Receives `(action, already_applied)`; a plain history unless the plugin sets its own.
var committer: Callable
## The plain history used when no committer is set.
var history := ActionHistory.new()
# The last selected_arc() answer and what it was computed from (the overlay asks each frame).
var _arc_for: Array = []
var _arc: Dictionary = {}
# The selected items' ItemKeys, in selection order.
var _selected_keys: Array = []


func _init(on_level: BoardLevel = null) -> void:
	level = on_level
	committer = history.commit
	if level != null:
		grid_step = 5.0 if level.is_maze() else 10.0


## Records an action: runs it (unless a live preview already did) and keeps it undoable.
func commit(action: BoardAction, already_applied := false) -> void:
	committer.call(action, already_applied)
	prune_selection()
	edited.emit()


## `point` snapped to the editor grid when snapping is on.
func snap_point(point: Vector2) -> Vector2:
	return Snapping.to_grid(point, grid_step) if snap_enabled else point


## Where a cell-sized thing (hole, start, goal) goes: the maze cell centre when snapping on
## a maze, else the snapped point.
func snap_cell_point(point: Vector2) -> Vector2:
	if snap_enabled and level.is_maze():
		return Snapping.to_maze_cell_center(level, point)
	return snap_point(point)


## Where a wall end goes: a maze grid crossing when snapping, else free.
func snap_wall_point(point: Vector2) -> Vector2:
	if snap_enabled and level.is_maze():
		return Snapping.to_maze_corner(level, point)
	return point


## The mirror axis x, or NAN when mirror mode is off.
func mirror_axis() -> float:
	return Mirror.axis_of(level) if mirror_enabled else NAN


## An item set with its mirror image added when mirror mode is on.
func mirrored(data: Dictionary) -> Dictionary:
	return Mirror.mirror_set(data, Mirror.axis_of(level)) if mirror_enabled else data


## Turns grid snapping on or off.
func set_snap(enabled: bool) -> void:
	snap_enabled = enabled
	settings_changed.emit()


## Turns mirror mode on or off.
func set_mirror(enabled: bool) -> void:
	mirror_enabled = enabled
	settings_changed.emit()


## Hides or shows, locks or unlocks a layer; its items leave the selection.
func set_layer(layer: String, hidden: bool, locked: bool) -> void:
	for state: Array in [[hidden_layers, hidden], [locked_layers, locked]]:
		var names: Array[String] = state[0]
		if state[1] and not names.has(layer):
			names.append(layer)
		elif not state[1]:
			names.erase(layer)
	var kept: Array[Vector2i] = []
	for item in selection:
		if can_pick(item):
			kept.append(item)
	if kept != selection:
		select(kept)
	settings_changed.emit()


## False for an item on a hidden or locked layer: tools cannot pick, move or erase it.
func can_pick(item: Vector2i) -> bool:
	var layer := Layers.of_item(item)
	return not (hidden_layers.has(layer) or locked_layers.has(layer))


## Switches tool (ignores tools the board's kind has no use for).
func set_tool(new_tool: int) -> void:
	if not available_tools().has(new_tool) or new_tool == tool:
		return
	tool = new_tool
	tool_changed.emit(tool)


## The tools that apply to this board: its game's, then the place tools its rows bring.
func available_tools() -> Array[int]:
	var found: Array[int] = []
	found.assign(MAZE_TOOLS if level != null and level.is_maze() else PACHINKO_TOOLS)
	var game := level.kind if level != null else BoardLevel.Kind.PACHINKO
	var rows := row_tools()
	for row_tool in rows:
		if rows[row_tool].game == game:
			found.append(row_tool)
	return found


## The place tools the ItemKinds rows bring (ItemKind.tool_key: a floor arrow's), tool ->
## its row, numbered on from Tool's in table order.
static func row_tools() -> Dictionary[int, ItemKind]:
	var found: Dictionary[int, ItemKind] = {}
	for kind in ItemKinds.all():
		if kind.tool_key != KEY_NONE:
			found[Tool.size() + found.size()] = kind
	return found


## Replaces the selection.
func select(items: Array[Vector2i]) -> void:
	selection = items.duplicate()
	_selected_keys.clear()
	for item in selection:
		var key := ItemKeys.of(level, item)
		if not key.is_empty():
			_selected_keys.append(key)
	selection_changed.emit()


## Brings the selection up to date after an edit, an undo or a redo: each selected item where
## it is numbered now (found by its id), and those that no longer exist dropped.
func prune_selection() -> void:
	var kept := ItemKeys.find_all(level, _selected_keys)
	if kept != selection:
		select(kept)


## The pocket the dock's inspector edits: the only selected pocket, or -1.
func selected_pocket() -> int:
	var pockets := BoardItems.indices_of(selection, BoardItems.Kind.POCKET)
	return pockets[0] if pockets.size() == 1 else -1


## The pin arc the selection forms (PinArc.of_selection), or {}; remembered until the
## selection or the pins change.
func selected_arc() -> Dictionary:
	if level == null:
		return {}
	if _arc_for.size() == 2 and _arc_for[0] == selection and _arc_for[1] == level.pins:
		return _arc
	_arc = PinArc.of_selection(level, selection)
	_arc_for = [selection.duplicate(), level.pins]
	return _arc
