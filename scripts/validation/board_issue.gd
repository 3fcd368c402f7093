class_name BoardIssue
extends RefCounted
## One problem `BoardValidator` found on a board: how bad it is, a sentence for the
## designer, where to draw the marker, and a short code for tools and tests.

enum Severity { ERROR, WARNING }

## ERROR: the board cannot be loaded or played as it is. WARNING: playable, but likely a
## design mistake.
var severity: Severity = Severity.ERROR
## What is wrong, written for a board designer.
var message: String = ""
## Where on the board (pixels) the problem is, for drawing a marker.
var position: Vector2 = Vector2.ZERO
## Stable short code, e.g. "pin_overlap", "wall_zero_length" (see BoardValidator).
var kind: String = ""


func _init(
	issue_severity: Severity = Severity.ERROR,
	issue_message: String = "",
	at: Vector2 = Vector2.ZERO,
	code: String = ""
) -> void:
	severity = issue_severity
	message = issue_message
	position = at
	kind = code


## Appends a new issue to `issues`: the one way the validator's checks report a problem.
static func add_to(
	issues: Array[BoardIssue], issue_severity: Severity, text: String, at: Vector2, code: String
) -> void:
	issues.append(BoardIssue.new(issue_severity, text, at, code))


## True for an error (the board is refused by the loader).
func is_error() -> bool:
	return severity == Severity.ERROR


func _to_string() -> String:
	var label := "error" if is_error() else "warning"
	return "%s [%s] at (%.1f, %.1f): %s" % [label, kind, position.x, position.y, message]
