class_name MazeFraming
extends RefCounted
## Frames the tilted maze board in a region of the screen (the part the side panel leaves):
## an off-centre perspective (a camera frustum shifted like a view camera's lens) so the
## board sits in its region seen straight on, scaled so that every corner of the board,
## frame included, under any tilt stays inside the region at any window size and aspect.
## The camera never moves while a board is played: the player always sees the whole board.
## A board whose balls would be drawn smaller than MIN_BALL_PX at 1280 × 720 is made with
## fewer, wider corridors (tests/integration/test_maze_framing.gd checks every shipped one).
## Units: 3D units in the stage's space (camera on +z looking down -z), screen pixels.

## The smallest a ball may be drawn on a 1280 × 720 window, in pixels across (a design
## rule the shipped boards are made to; the camera never zooms in on part of the board).
const MIN_BALL_PX := 14.0
## Space kept free round the board inside its region (px).
const MARGIN_PX := 8.0

## The camera's distance from the board's centre, and its near plane (units).
var distance := 6.0
var near := 0.05
## The frustum's height at the near plane (Camera3D.size with KEEP_HEIGHT).
var size := 1.0
## The frustum's centre at the near plane (Camera3D.frustum_offset).
var offset := Vector2.ZERO
## How many pixels across a ball is drawn (at the board's height, untilted), in the view's
## units.
var ball_px := 0.0
## The width over the height of the board the camera last fitted (its frame's corners under
## every tilt, as seen): above the region's own shape the board is drawn by its width and
## leaves room above and below it (MazePanelLayout narrows the side column then).
var board_aspect := 0.0

var _view := Vector2(1280.0, 720.0)
var _region := Rect2(0.0, 0.0, 1280.0, 720.0)
## View units per screen unit at the near plane.
var _k := 1.0


## Fits `points` (the board's outer corners under every tilt it can take) into `area`
## of a `view`-sized screen, for balls `ball_diameter` units across.
func fit(points: PackedVector3Array, view: Vector2, area: Rect2, ball_diameter: float) -> void:
	_view = Vector2(maxf(view.x, 1.0), maxf(view.y, 1.0))
	_region = area.grow(-MARGIN_PX)
	if _region.size.x < 1.0 or _region.size.y < 1.0:
		_region = Rect2(Vector2.ZERO, _view)
	var bounds := Rect2(_at_near(points[0]), Vector2.ZERO)
	for p in points:
		bounds = bounds.expand(_at_near(p))
	_k = maxf(bounds.size.x / _region.size.x, bounds.size.y / _region.size.y)
	size = _k * _view.y
	ball_px = ball_diameter * near / distance / _k
	var shift := _region.get_center() - _view * 0.5
	offset = bounds.get_center() - Vector2(shift.x, -shift.y) * _k


## The width over the height of `points` (stage units) as the camera sees them.
func aspect_of(points: PackedVector3Array) -> float:
	if points.is_empty():
		return 0.0
	var bounds := Rect2(_at_near(points[0]), Vector2.ZERO)
	for p in points:
		bounds = bounds.expand(_at_near(p))
	return bounds.size.x / bounds.size.y if bounds.size.y > 0.0 else 0.0


## Where `p` (stage units) is drawn on the screen, in pixels from the top left.
func project(p: Vector3) -> Vector2:
	var q := _at_near(p) - offset
	return _view * 0.5 + Vector2(q.x, -q.y) / _k


## The region the board is fitted into (margins taken off).
func region() -> Rect2:
	return _region


# `p` seen from the camera, on its near plane.
func _at_near(p: Vector3) -> Vector2:
	var depth := maxf(distance - p.z, 0.001)
	return Vector2(p.x, p.y) * near / depth
