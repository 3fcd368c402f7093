@tool
class_name BoardNode
extends Node2D
## Shows a BoardLevel in a scene. In a level scene (scenes/boards/) it is the node the board
## editor plugin takes over; it redraws whenever the level changes and lists the
## validator's findings as configuration warnings.

## At most this many validator findings are listed as configuration warnings.
const MAX_WARNINGS := 12

## The board shown and edited. Saving the scene saves this resource's own .board file.
@export var level: BoardLevel:
	set(value):
		if level == value:
			return
		if level != null and level.changed.is_connected(_on_level_changed):
			level.changed.disconnect(_on_level_changed)
		level = value
		if level != null:
			level.changed.connect(_on_level_changed)
		_on_level_changed()
## Which BoardPainter layers to draw.
@export_flags(
	"Background",
	"Ring",
	"Rail",
	"Gutter",
	"Pins",
	"Pockets",
	"Walls",
	"Holes",
	"Goal",
	"Starts",
	"Bonus pockets",
	"Windmills",
	"Floor arrows"
)
var layers: int = BoardPainter.Layer.ALL:
	set(value):
		layers = value
		queue_redraw()

## BoardPainter layers the board editor hides for now (its layer panel); never saved.
var editor_hidden_layers := 0:
	set(value):
		editor_hidden_layers = value
		queue_redraw()

var _issues: Array[BoardIssue] = []
var _issues_stale := true


func _draw() -> void:
	BoardPainter.draw_board(self, level, Transform2D.IDENTITY, layers & ~editor_hidden_layers)


func _get_configuration_warnings() -> PackedStringArray:
	var warnings := PackedStringArray()
	if level == null:
		warnings.append(
			"Assign a BoardLevel (a .board file from levels/) to show and edit a board."
		)
		return warnings
	var found := issues()
	for issue: BoardIssue in found.slice(0, MAX_WARNINGS):
		var label := "Error" if issue.is_error() else "Warning"
		warnings.append("%s: %s" % [label, issue.message])
	if found.size() > MAX_WARNINGS:
		warnings.append("... and %d more." % (found.size() - MAX_WARNINGS))
	return warnings


## The validator's findings for the current level (cached until the level changes).
func issues() -> Array[BoardIssue]:
	if _issues_stale:
		_issues = BoardValidator.validate(level) if level != null else ([] as Array[BoardIssue])
		_issues_stale = false
	return _issues


func _on_level_changed() -> void:
	_issues_stale = true
	queue_redraw()
	if Engine.is_editor_hint():
		update_configuration_warnings()
