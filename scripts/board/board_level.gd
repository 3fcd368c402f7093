@tool
class_name BoardLevel
extends Resource
## One board, pachinko or maze, saved as a `.board` file (JSON Lines, BoardTextWriter) in
## `levels/<kind>/`.
##
## Both kinds share this model; each uses its own group of fields. Units are pixels, angles
## are degrees (y down, 0 = right, 90 = down). Defaults are deliberately empty (zero sizes,
## no pins) so a field missing from a file shows up as a validation error rather than a
## plausible-looking board. Use `create_pachinko()` / `create_maze()` for a fresh board.
## Setters emit `changed`; after editing a packed array in place call `notify_edited()`.

enum Kind { PACHINKO, MAZE }
## Each Kind's name, in Kind order: the one spelling of a game wherever it is text (a board
## file's "kind", the folders levels/<name>/ and user://boards/<name>/, a replay's "game",
## the command line, the game scenes).
const KIND_NAMES: Array[String] = ["pachinko", "maze"]
## KIND_NAMES[Kind.PACHINKO] and KIND_NAMES[Kind.MAZE], for code that names one game.
const PACHINKO_NAME: String = KIND_NAMES[Kind.PACHINKO]
const MAZE_NAME: String = KIND_NAMES[Kind.MAZE]

## The format this code writes. Older files are upgraded by the converter (tools/legacy_boards/).
const CURRENT_VERSION := 1

@export_group("Common")
## File format version; older files are upgraded on load.
@export var version: int = 0:
	set(value):
		version = value
		emit_changed()
## Which game this board is for.
@export var kind: Kind = Kind.PACHINKO:
	set(value):
		kind = value
		emit_changed()
## Stable id used for save data (best times, best scores).
@export var board_id: String = "":
	set(value):
		board_id = value
		emit_changed()
## Name shown in the level select.
@export var display_name: String = "":
	set(value):
		display_name = value
		emit_changed()
## One or two sentences for the level select.
@export var description: String = "":
	set(value):
		description = value
		emit_changed()
## Board size in pixels; the board spans (0, 0) to size.
@export var size: Vector2 = Vector2.ZERO:
	set(value):
		size = value
		emit_changed()
## Radius of every ball on this board, in pixels.
@export var ball_radius: float = 0.0:
	set(value):
		ball_radius = value
		emit_changed()
## Physics constants for this board.
@export var tuning: PhysicsTuning = null:
	set(value):
		tuning = value
		emit_changed()

@export_group("Pachinko")
## Centre of the ring border.
@export var ring_center: Vector2 = Vector2.ZERO:
	set(value):
		ring_center = value
		emit_changed()
## Inside radius of the ring border; balls stay inside it.
@export var ring_radius: float = 0.0:
	set(value):
		ring_radius = value
		emit_changed()
## Width of the launch channel between the ring and the inner guide arc.
@export var rail_width: float = 0.0:
	set(value):
		rail_width = value
		emit_changed()
## Angle where the launch channel starts (the launcher), degrees, y down.
@export var rail_start_deg: float = 0.0:
	set(value):
		rail_start_deg = value
		emit_changed()
## Angle where the channel opens into the field, degrees. The ball travels from start to
## end through decreasing angles (up the right side and over the top).
@export var rail_end_deg: float = 0.0:
	set(value):
		rail_end_deg = value
		emit_changed()
## Start of the gutter arc at the bottom of the ring, degrees.
@export var gutter_start_deg: float = 0.0:
	set(value):
		gutter_start_deg = value
		emit_changed()
## End of the gutter arc, degrees (greater than the start).
@export var gutter_end_deg: float = 0.0:
	set(value):
		gutter_end_deg = value
		emit_changed()
## Ring contacts inside the gutter arc before a ball is drained.
@export var gutter_bounces: int = 0:
	set(value):
		gutter_bounces = value
		emit_changed()
## Pin centres, in pixels.
@export var pins: PackedVector2Array = PackedVector2Array():
	set(value):
		pins = value
		emit_changed()
## Radius of every pin, in pixels.
@export var pin_radius: float = 0.0:
	set(value):
		pin_radius = value
		emit_changed()
## Per pin: index into pockets, or -1 for a field pin.
@export var pin_pocket: PackedInt32Array = PackedInt32Array():
	set(value):
		pin_pocket = value
		emit_changed()
## Per pin: 1 for a pocket's special (catching) pin, else 0.
@export var pin_special: PackedByteArray = PackedByteArray():
	set(value):
		pin_special = value
		emit_changed()
## The pockets; pins refer to them by index.
@export var pockets: Array[PocketSpec] = []:
	set(value):
		pockets = value
		_watch_pockets()
		emit_changed()
## Balls in the cup when a game starts.
@export var cup_start_balls: int = 0:
	set(value):
		cup_start_balls = value
		emit_changed()
## The machine the board is dressed as (FasciaNames: art, palette, name plate). Looks only:
## it never changes how the board plays.
@export var fascia: String = FasciaNames.CLASSIC:
	set(value):
		fascia = value
		emit_changed()

## The bonus layer: start pockets, attackers and tulips (BonusPocketSpec), start pockets
## first, then attackers, then tulips. Their pins are not in `pins`: the world factory
## stamps them from these specs (BonusGeometry).
@export var bonus_pockets: Array[BonusPocketSpec] = []:
	set(value):
		bonus_pockets = value
		_watch_pockets()
		emit_changed()

## The windmills (WindmillSpec): wheels of blades the world turns (BallWorld.add_windmill).
@export var windmills: Array[WindmillSpec] = []:
	set(value):
		windmills = value
		_watch_pockets()
		emit_changed()

@export_group("Maze")
## Maze cells across.
@export var grid_cols: int = 0:
	set(value):
		grid_cols = value
		emit_changed()
## Maze cells down.
@export var grid_rows: int = 0:
	set(value):
		grid_rows = value
		emit_changed()
## Width of a corridor, in pixels.
@export var path_width: float = 0.0:
	set(value):
		path_width = value
		emit_changed()
## Thickness of a wall (capsule diameter), in pixels.
@export var wall_width: float = 0.0:
	set(value):
		wall_width = value
		emit_changed()
## Wall centre lines as pairs of points a, b (capsules with round caps).
@export var walls: PackedVector2Array = PackedVector2Array():
	set(value):
		walls = value
		emit_changed()
## Where the balls start, one ball per point.
@export var ball_starts: PackedVector2Array = PackedVector2Array():
	set(value):
		ball_starts = value
		emit_changed()
## Centre of the goal zone.
@export var goal_center: Vector2 = Vector2.ZERO:
	set(value):
		goal_center = value
		emit_changed()
## Radius of the goal zone; a ball counts when its centre is inside.
@export var goal_radius: float = 0.0:
	set(value):
		goal_radius = value
		emit_changed()
## Black hole centres (hard mode only).
@export var holes: PackedVector2Array = PackedVector2Array():
	set(value):
		holes = value
		emit_changed()
## Floor arrows (FloorArrowSpec): hints painted on the floor, no physics.
@export var floor_arrows: Array[FloorArrowSpec] = []:
	set(value):
		floor_arrows = value
		_watch_pockets()
		emit_changed()
## Radius of every black hole, in pixels.
@export var hole_radius: float = 0.0:
	set(value):
		hole_radius = value
		emit_changed()

## Medal times of easy mode in seconds, [gold, silver, bronze] (empty: no medals yet).
@export var medal_times_easy: PackedFloat64Array = PackedFloat64Array():
	set(value):
		medal_times_easy = value
		emit_changed()
## Medal times of hard mode in seconds, [gold, silver, bronze] (empty: no medals yet).
@export var medal_times_hard: PackedFloat64Array = PackedFloat64Array():
	set(value):
		medal_times_hard = value
		emit_changed()
## Stable ids of the items, one per item, in the same order (see ItemIds): they survive a
## neighbour being deleted, so messages and the editor can name an item for good.
@export var pin_ids: PackedInt32Array = PackedInt32Array():
	set(value):
		pin_ids = value
		emit_changed()
@export var pocket_ids: PackedInt32Array = PackedInt32Array():
	set(value):
		pocket_ids = value
		emit_changed()
@export var wall_ids: PackedInt32Array = PackedInt32Array():
	set(value):
		wall_ids = value
		emit_changed()
@export var hole_ids: PackedInt32Array = PackedInt32Array():
	set(value):
		hole_ids = value
		emit_changed()
@export var start_ids: PackedInt32Array = PackedInt32Array():
	set(value):
		start_ids = value
		emit_changed()
## Ids of the bonus pockets, one array per role, each in board order among its role.
@export var start_pocket_ids: PackedInt32Array = PackedInt32Array():
	set(value):
		start_pocket_ids = value
		emit_changed()
@export var attacker_ids: PackedInt32Array = PackedInt32Array():
	set(value):
		attacker_ids = value
		emit_changed()
@export var tulip_ids: PackedInt32Array = PackedInt32Array():
	set(value):
		tulip_ids = value
		emit_changed()
@export var windmill_ids: PackedInt32Array = PackedInt32Array():
	set(value):
		windmill_ids = value
		emit_changed()
@export var floor_arrow_ids: PackedInt32Array = PackedInt32Array():
	set(value):
		floor_arrow_ids = value
		emit_changed()
## Per item list ("pins", "walls"...): the id the next new item of that list gets. It only
## ever grows, so an id is never handed out twice in a board's life, even after the item
## that had the highest id is deleted (ItemIds.next_id; a list missing here starts after its
## largest id).
@export var next_ids: Dictionary[String, int] = {}:
	set(value):
		next_ids = value
		emit_changed()

## Fields of older file layouts that this version no longer declares, kept during a load so
## the converter (tools/legacy_boards/board_upgrader.gd) can convert them. Never saved.
var legacy_fields: Dictionary = {}

var _watched: Array[Resource] = []


func _init() -> void:
	# A board made in code is current; a file's own `version` line overrides this on load.
	version = CURRENT_VERSION


# A loading file may carry fields of an older layout: keep them for the upgrader instead of
# dropping them silently.
func _set(property: StringName, value: Variant) -> bool:
	if String(property).begins_with("metadata/") or property == &"script":
		return false
	legacy_fields[String(property)] = value
	return true


## Tells listeners (the board node, the editor) that the board changed after an in-place
## edit of one of its arrays, which the setters cannot see.
func notify_edited() -> void:
	_watch_pockets()
	emit_changed()


## An independent copy: pockets, bonus pockets, windmills (every item resource) and tuning
## are copied too, so editing the copy never touches this board (Resource.duplicate shares
## sub-resources inside arrays).
func duplicate_level() -> BoardLevel:
	var copy := duplicate(false) as BoardLevel
	for field in _spec_fields():
		var specs: Array = get(field)
		var copies := specs.duplicate()  # keeps the typed array's type
		for i in copies.size():
			var spec: Resource = copies[i]
			copies[i] = spec.duplicate() if spec != null else null
		copy.set(field, copies)
	copy.tuning = tuning.duplicate() as PhysicsTuning if tuning != null else null
	copy.next_ids = next_ids.duplicate()
	copy.legacy_fields = legacy_fields.duplicate(true)
	return copy


## True for a pachinko board.
func is_pachinko() -> bool:
	return kind == Kind.PACHINKO


## True for a maze board.
func is_maze() -> bool:
	return kind == Kind.MAZE


## The name of a kind (KIND_NAMES); an unknown kind is named as pachinko, the first.
static func kind_name(of_kind: int) -> String:
	return KIND_NAMES[of_kind] if of_kind >= 0 and of_kind < KIND_NAMES.size() else PACHINKO_NAME


## The Kind called `name` (KIND_NAMES), or -1 when it is no game's name (or no text).
static func kind_named(name: Variant) -> int:
	return KIND_NAMES.find(name) if name is String else -1


## The names of the kinds for a message: "pachinko" or "maze" (quoted).
static func kind_choices() -> String:
	return " or ".join(KIND_NAMES.map(func(name: String) -> String: return '"%s"' % name))


# An item resource (a pocket, a windmill...) edited on its own (in the inspector, say)
# changes the board too.
func _watch_pockets() -> void:
	for spec in _watched:
		if spec != null and spec.changed.is_connected(emit_changed):
			spec.changed.disconnect(emit_changed)
	_watched.clear()
	var watch: Array[Resource] = []
	for field in _spec_fields():
		var specs: Array = get(field)
		watch.append_array(specs)
	for spec in watch:
		if spec != null and not spec.changed.is_connected(emit_changed):
			spec.changed.connect(emit_changed)
			_watched.append(spec)


# The fields holding item resources (pockets, bonus pockets, windmills): every stored typed
# Array of objects. Found from the property list, not named here, so a new kind of item
# resource is copied and watched with no change to this file (which ItemKinds cannot be
# used from: the table's rows are typed with BoardLevel).
func _spec_fields() -> Array[String]:
	var fields: Array[String] = []
	for property in get_property_list():
		var usage: int = property["usage"]
		if property["type"] != TYPE_ARRAY or not usage & PROPERTY_USAGE_STORAGE:
			continue
		var name: String = property["name"]
		var value: Array = get(name)
		if value.get_typed_builtin() == TYPE_OBJECT:
			fields.append(name)
	return fields
