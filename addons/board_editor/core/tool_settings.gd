@tool
extends RefCounted
## The designer's tool settings, carried from one edited board to the next: the plugin
## makes a new session for every board it edits (a scene tab switch, a reselect), and
## without this the tool, snap, grid, mirror, pattern, curve, pocket sizes and the
## clipboard would start over each time. The tool itself is kept only where the new
## board's kind offers it (a wall tool does not carry over to a pachinko board).

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")

## The session fields kept, copied as values.
const FIELDS: Array[String] = [
	"snap_enabled",
	"grid_step",
	"mirror_enabled",
	"pattern",
	"curve",
	"pocket_width",
	"pocket_depth",
	"pocket_payout",
	"clipboard",
]


## The settings of `session`, ready for `apply`.
static func capture(session: BoardEditSession) -> Dictionary:
	var kept := {"tool": session.tool}
	for field in FIELDS:
		kept[field] = _copy(session.get(field))
	return kept


## Puts `kept` (from `capture`) on `session`; the tool only when the board offers it.
static func apply(session: BoardEditSession, kept: Dictionary) -> void:
	for field in FIELDS:
		if kept.has(field):
			session.set(field, _copy(kept[field]))
	var tool: int = kept.get("tool", BoardEditSession.Tool.SELECT)
	if session.available_tools().has(tool):
		session.set_tool(tool)
	session.settings_changed.emit()


# A value as its own copy: dictionaries deep-copied, so the two sessions never share one.
static func _copy(value: Variant) -> Variant:
	if value is Dictionary:
		var table: Dictionary = value
		return table.duplicate(true)
	return value
