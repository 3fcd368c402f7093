extends RefCounted
## Frames the tilted maze board in a region of the screen (the part the side panel leaves):
## an off-centre perspective (a camera frustum shifted like a view camera's lens) so the
## board sits in its region seen straight on, scaled so that every corner of the board under
## any tilt stays inside the region at any window size and aspect. When that would draw a
## ball smaller than `min_ball_px()`, it zooms in until a ball is that big and follows the
## balls (`frame_balls`): zoomed out again as far as it takes to keep every ball on screen
## (never further than the whole board), aimed at their middle and held so the view never
## leaves the board.
## Units: 3D units in the stage's space (camera on +z looking down -z), screen pixels.

## A ball is never drawn smaller than this many pixels across on a 720-pixel-high screen
## (on smaller screens, proportionally smaller, down to half).
const MIN_BALL_PX := 14.0
const REFERENCE_SCREEN := 720.0
## Space kept free round the board inside its region (px).
const MARGIN_PX := 8.0
## Space kept round the balls in a zoomed view, in ball radii beyond each ball's edge.
const BALL_MARGIN_RADII := 1.5

## The camera's distance from the board's centre, and its near plane (units).
var distance := 6.0
var near := 0.05
## The frustum's height at the near plane (Camera3D.size with KEEP_HEIGHT).
var size := 1.0
## The frustum's centre at the near plane (Camera3D.frustum_offset).
var offset := Vector2.ZERO
## True when the board is larger than its region at the smallest ball size: the view
## follows `follow()`'s point instead of showing the whole board.
var zoomed := false
## How many pixels across a ball is drawn (at the board's height), in the view's units.
var ball_px := 0.0
## Screen pixels per view unit (the window's stretch: 1 when the view is drawn 1:1).
var screen_scale := 1.0

var _view := Vector2(1280.0, 720.0)
var _region := Rect2(0.0, 0.0, 1280.0, 720.0)
var _bounds := Rect2()
var _k := 1.0
## The scale (view units per screen unit at the near plane) that shows the whole board, and
## the closest one (a ball at min_ball_px).
var _k_board := 1.0
var _k_close := 1.0
var _ball_near := 0.0


## Fits `points` (the board's outer corners under every tilt it can take) into `area`
## of a `view`-sized screen, for balls `ball_diameter` units across.
func fit(points: PackedVector3Array, view: Vector2, area: Rect2, ball_diameter: float) -> void:
	_view = Vector2(maxf(view.x, 1.0), maxf(view.y, 1.0))
	_region = area.grow(-MARGIN_PX)
	if _region.size.x < 1.0 or _region.size.y < 1.0:
		_region = Rect2(Vector2.ZERO, _view)
	_bounds = Rect2(_at_near(points[0]), Vector2.ZERO)
	for p in points:
		_bounds = _bounds.expand(_at_near(p))
	_k_board = maxf(_bounds.size.x / _region.size.x, _bounds.size.y / _region.size.y)
	_ball_near = ball_diameter * near / distance
	_k_close = _ball_near / min_ball_px()
	zoomed = _k_board > _k_close
	_set_scale(_k_close if zoomed else _k_board)
	follow(_bounds.get_center() * distance / near)


## Points the zoomed view at `centre` (a point on the board's plane, units): it comes to the
## region's centre as far as the board's edges allow. Unzoomed, the board stays centred.
func follow(centre: Vector2) -> void:
	var aim := _bounds.get_center()
	if zoomed:
		var want := centre * near / distance
		var half := _region.size * _k * 0.5
		aim = Vector2(
			_clamp_axis(want.x, _bounds.position.x, _bounds.end.x, half.x),
			_clamp_axis(want.y, _bounds.position.y, _bounds.end.y, half.y)
		)
	var shift := _region.get_center() - _view * 0.5
	offset = aim - Vector2(shift.x, -shift.y) * _k


## The box round `balls` (stage points of the balls' centres, each `radius` units) as the
## camera sees it (near-plane units), with BALL_MARGIN_RADII round each ball: what
## `frame_box` must keep on screen.
func balls_box(balls: PackedVector3Array, radius: float) -> Rect2:
	if balls.is_empty():
		return Rect2()
	var box := Rect2(_at_near(balls[0]), Vector2.ZERO)
	var reach := 0.0
	for p in balls:
		box = box.expand(_at_near(p))
		reach = maxf(reach, radius * (1.0 + BALL_MARGIN_RADII) * near / maxf(distance - p.z, 0.001))
	return box.grow(reach)


## Frames a zoomed view on `box` (near-plane units, from `balls_box`): as close as a ball
## at min_ball_px allows, further out when the box is bigger than that view (up to the
## whole board), aimed at the box's middle as far as the board's edges allow. Unzoomed, the
## whole board stays in view and nothing changes.
func frame_box(box: Rect2) -> void:
	if not zoomed:
		return
	var need := maxf(box.size.x / _region.size.x, box.size.y / _region.size.y)
	_set_scale(minf(maxf(_k_close, need), _k_board))
	follow(box.get_center() * distance / near)


## Where `p` (stage units) is drawn on the screen, in pixels from the top left.
func project(p: Vector3) -> Vector2:
	var q := _at_near(p) - offset
	return _view * 0.5 + Vector2(q.x, -q.y) / _k


## The smallest ball size for this screen, in view units (MIN_BALL_PX screen pixels on a
## screen at least REFERENCE_SCREEN pixels each way).
func min_ball_px() -> float:
	var screen := _view * screen_scale
	var wanted := MIN_BALL_PX * clampf(minf(screen.x, screen.y) / REFERENCE_SCREEN, 0.5, 1.0)
	return wanted / maxf(screen_scale, 0.01)


## The region the board is fitted into (margins taken off).
func region() -> Rect2:
	return _region


# Sets the view's scale: its frustum size and how big a ball is drawn.
func _set_scale(k: float) -> void:
	_k = k
	size = _k * _view.y
	ball_px = _ball_near / _k


# `p` seen from the camera, on its near plane.
func _at_near(p: Vector3) -> Vector2:
	var depth := maxf(distance - p.z, 0.001)
	return Vector2(p.x, p.y) * near / depth


# `want` held inside [lo + half, hi - half]; the middle when the window is wider than that.
static func _clamp_axis(want: float, lo: float, hi: float, half: float) -> float:
	if hi - lo <= half * 2.0:
		return (lo + hi) * 0.5
	return clampf(want, lo + half, hi - half)
