@tool
extends RefCounted
## The board editor's keyboard shortcuts. Editor plugins cannot use the game's input map,
## so the editor keys live here, in one table, shown in every tooltip. Undo and redo are
## the editor's own Ctrl+Z / Ctrl+Shift+Z. The letters avoid Godot's own 2D keys (W move,
## E rotate, S scale, R ruler, V pivot, G pan); Q picks Select, as it does in Godot. While a
## board is edited every plain key over the viewport is the board tool's (BoardInput), so a
## letter with no use here does nothing rather than switching a Godot tool.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")

## Tool -> [key, name, tooltip].
const TOOLS := {
	BoardEditSession.Tool.SELECT:
	[KEY_Q, "Select", "Click to pick, drag a box, shift adds, ctrl toggles; drag to move."],
	BoardEditSession.Tool.PIN: [KEY_P, "Pin", "Click to place a pin."],
	BoardEditSession.Tool.PATTERN:
	[KEY_T, "Pattern", "Click to stamp a row, lattice, arc or circle of pins (set in the dock)."],
	BoardEditSession.Tool.CURVE:
	[
		KEY_C,
		"Peg curve",
		"Drag a curve: pins follow it, a set count end to end or one every spacing (dock)."
	],
	BoardEditSession.Tool.POCKET:
	[KEY_K, "Pocket", "Click to add a pocket: rim pins and special pin, sized in the dock."],
	BoardEditSession.Tool.WALL:
	[KEY_L, "Wall", "Click-drag a wall; snapped to the maze grid or free."],
	BoardEditSession.Tool.HOLE: [KEY_O, "Black hole", "Click to place a black hole (hard mode)."],
	BoardEditSession.Tool.GOAL:
	[KEY_U, "Goal", "Click to move the goal; resize it with the handles tool."],
	BoardEditSession.Tool.START:
	[KEY_B, "Ball start", "Click to add a ball start (one ball each)."],
	BoardEditSession.Tool.HANDLES:
	[KEY_D, "Handles", "Drag the ring, launch rail and gutter handles, or the goal's radius."],
	BoardEditSession.Tool.ERASE:
	[
		KEY_X,
		"Erase",
		(
			"Click a pin, pocket, bonus pocket, windmill, wall, hole or start to delete it; drag"
			+ " across many."
		)
	],
	BoardEditSession.Tool.START_POCKET:
	[
		KEY_J,
		"Start pocket",
		"Click to add a start pocket (spins the reels); click one to remove it."
	],
	BoardEditSession.Tool.ATTACKER:
	[KEY_A, "Attacker", "Click to add an attacker (opens on a jackpot); click one to remove it."],
	BoardEditSession.Tool.TULIP:
	[KEY_F, "Tulip", "Click to add a tulip (opens after a catch); click one to remove it."],
	BoardEditSession.Tool.WINDMILL:
	[
		KEY_I,
		"Windmill",
		(
			"Click to add a windmill: four blades turning clockwise (set blades, speed or free"
			+ " spin with the select tool)."
		)
	],
}
## Toggles.
const SNAP_KEY := KEY_N
const MIRROR_KEY := KEY_M
## Commands on the selection: H flips it left to right about its centre, Shift+M adds its
## mirror image on the other half of the board.
const FLIP_KEY := KEY_H
const MIRROR_COPY_KEY := KEY_M


## Every tool, TOOLS and then those the ItemKinds rows bring (BoardEditSession.row_tools): tool ->
## [key, name, tooltip].
static func tools() -> Dictionary:
	var found := TOOLS.duplicate()
	var rows := BoardEditSession.row_tools()
	for tool in rows:
		found[tool] = [rows[tool].tool_key, rows[tool].singular, rows[tool].tool_tip]
	return found


## The tool's name ("Pin").
static func name_of(tool: int) -> String:
	var entry: Array = tools()[tool]
	return entry[1]


## The key that picks a tool.
static func key_of(tool: int) -> Key:
	var entry: Array = tools()[tool]
	return entry[0]


## "Name (Key)" for a tool.
static func label(tool: int) -> String:
	return "%s (%s)" % [name_of(tool), OS.get_keycode_string(key_of(tool))]


## The tooltip text for a tool.
static func tooltip(tool: int) -> String:
	var entry: Array = tools()[tool]
	return "%s\n%s" % [label(tool), entry[2]]


## The tool a plain key press selects, or -1.
static func tool_for(event: InputEventKey) -> int:
	if event.ctrl_pressed or event.alt_pressed or event.meta_pressed or event.shift_pressed:
		return -1
	for tool: int in tools():
		if key_of(tool) == event.keycode:
			return tool
	return -1
