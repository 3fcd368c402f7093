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
## The board area the problem covers when it is more than a point (both pins of an overlap,
## a start and the goal it cannot reach, a ring that pokes out): the editor's jump frames
## all of it. Empty for a problem at `position` alone.
var area: Rect2 = Rect2()
## Walls to point at, as pairs of ends (the walls that close a goal or a start in): the
## editor draws them in the problem's colour. Empty for most problems.
var segments: PackedVector2Array = PackedVector2Array()


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


## Like `add_to`, for a problem that covers `covers` (board pixels), not one point.
static func add_covering(
	issues: Array[BoardIssue],
	issue_severity: Severity,
	text: String,
	at: Vector2,
	code: String,
	covers: Rect2
) -> void:
	var issue := BoardIssue.new(issue_severity, text, at, code)
	issue.area = covers.abs()
	issues.append(issue)


## The rectangle around two circles (centre, radius): what an issue about them covers.
static func around(a: Vector2, a_radius: float, b: Vector2, b_radius: float) -> Rect2:
	var box := Rect2(a - Vector2.ONE * a_radius, Vector2.ONE * a_radius * 2.0)
	return box.merge(Rect2(b - Vector2.ONE * b_radius, Vector2.ONE * b_radius * 2.0))


## What a view should show of the problem: `area` with the marker in it, or the marker alone.
func extent() -> Rect2:
	if not area.is_finite() or not position.is_finite():
		return Rect2(position if position.is_finite() else Vector2.ZERO, Vector2.ZERO)
	if area.has_area():
		return area.expand(position)
	return Rect2(position, Vector2.ZERO)


## True for an error (the board is refused by the loader).
func is_error() -> bool:
	return severity == Severity.ERROR


func _to_string() -> String:
	var label := "error" if is_error() else "warning"
	return "%s [%s] at (%.1f, %.1f): %s" % [label, kind, position.x, position.y, message]
