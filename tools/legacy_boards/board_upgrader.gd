extends RefCounted
## Brings boards saved by older versions up to `BoardLevel.CURRENT_VERSION`, one step at a
## time. Each step reads the old fields the loader kept in `level.legacy_fields`.
##
## Version 0 (the prototype format, files without a `version` line) differed from version 1:
## - pachinko pockets were parallel lists `pocket_positions` (PackedVector2Array),
##   `pocket_payouts` (PackedInt32Array) and one `pocket_size` (Vector2: width, depth)
##   instead of `pockets: Array[PocketSpec]`;
## - the rail and gutter arcs were Vector2s `rail_arc` / `gutter_arc` (start, end degrees)
##   instead of separate start and end fields;
## - maze walls were `wall_cells` (PackedInt32Array of column, row, length, horizontal 1/0
##   quadruples in grid cells of `cell_size` px, the tutorial's own notation) instead of
##   pixel segments in `walls`.

## Old field → the Variant type it had, for the loader's checks of old files.
const LEGACY_FIELDS := {
	"pocket_positions": TYPE_PACKED_VECTOR2_ARRAY,
	"pocket_payouts": TYPE_PACKED_INT32_ARRAY,
	"pocket_size": TYPE_VECTOR2,
	"rail_arc": TYPE_VECTOR2,
	"gutter_arc": TYPE_VECTOR2,
	"wall_cells": TYPE_PACKED_INT32_ARRAY,
	"cell_size": TYPE_FLOAT,
}


## Upgrades `level`, read from a file of `from_version`, in place. Returns "" on success or
## what could not be converted.
static func upgrade(level: BoardLevel, from_version: int) -> String:
	if from_version < 0 or from_version > BoardLevel.CURRENT_VERSION:
		return (
			"unknown version %d (this build reads 0 to %d)"
			% [from_version, BoardLevel.CURRENT_VERSION]
		)
	var version := from_version
	while version < BoardLevel.CURRENT_VERSION:
		var problem := ""
		match version:
			0:
				problem = _v0_to_v1(level)
		if not problem.is_empty():
			return "upgrading from version %d: %s" % [version, problem]
		version += 1
	if not level.legacy_fields.is_empty():
		return "unknown field(s) %s" % ", ".join(PackedStringArray(level.legacy_fields.keys()))
	level.version = BoardLevel.CURRENT_VERSION
	return ""


static func _v0_to_v1(level: BoardLevel) -> String:
	var old := level.legacy_fields
	if old.has("rail_arc"):
		var rail: Vector2 = old["rail_arc"]
		level.rail_start_deg = rail.x
		level.rail_end_deg = rail.y
	if old.has("gutter_arc"):
		var gutter: Vector2 = old["gutter_arc"]
		level.gutter_start_deg = gutter.x
		level.gutter_end_deg = gutter.y
	if old.has("pocket_positions"):
		var positions: PackedVector2Array = old["pocket_positions"]
		var payouts: PackedInt32Array = old.get("pocket_payouts", PackedInt32Array())
		var size: Vector2 = old.get("pocket_size", Vector2.ZERO)
		if payouts.size() != positions.size():
			return "%d pocket positions but %d payouts" % [positions.size(), payouts.size()]
		var pockets: Array[PocketSpec] = []
		for i in positions.size():
			pockets.append(PocketSpec.create(positions[i], size.x, size.y, payouts[i]))
		level.pockets = pockets
	if old.has("wall_cells"):
		var cells: PackedInt32Array = old["wall_cells"]
		var cell: float = old.get("cell_size", level.path_width + level.wall_width)
		if cells.size() % 4 != 0:
			return "wall_cells holds %d numbers, not groups of four" % cells.size()
		var walls := PackedVector2Array()
		@warning_ignore("integer_division")  # checked above: whole groups of four
		var wall_count := cells.size() / 4
		for w in wall_count:
			var start := Vector2(cells[w * 4], cells[w * 4 + 1]) * cell
			var length := cells[w * 4 + 2] * cell
			var horizontal := cells[w * 4 + 3] != 0
			walls.append(start)
			walls.append(start + (Vector2(length, 0.0) if horizontal else Vector2(0.0, length)))
		level.walls = walls
	for key: String in LEGACY_FIELDS:
		old.erase(key)
	return ""
