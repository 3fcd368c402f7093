extends RefCounted
## The capsule walls as one motion lane sees them: the grid's wall lists (copied by
## take()) and, for a ball, the deepest wall it overlaps in its cell (deepest()). What the
## contact does to the ball is BallMover's (its _touch_walls): this part only finds it.
## Internal to scripts/physics; each BallMover has one.

const StaticGeometry := preload("res://scripts/physics/static_geometry.gd")
const ContactMath := preload("res://scripts/physics/contact_math.gd")

## False on a board without walls.
var has_walls := false
## Walls of grid cell c: entries start[c] .. start[c + 1] of the lists below.
var start := PackedInt32Array()
# The contact deepest() found: how many walls the ball overlaps, the deepest one, its
# closest point to the ball, how far along the wall that is (0..1), the contact distance
# and the normal (to the ball).
var found := 0
var best := -1
var best_q := Vector2.ZERO
var best_s := 0.0
var best_lim := 0.0
var nrm := Vector2.ZERO

var _items := PackedInt32Array()
var _item_a := PackedVector2Array()
var _item_ab := PackedVector2Array()
var _item_inv := PackedFloat32Array()
var _item_rad := PackedFloat32Array()
var _wall_ab := PackedVector2Array()
var _wall_inv_len2 := PackedFloat32Array()


## Takes the grid's wall lists for this step.
func take(g: StaticGeometry) -> void:
	has_walls = not g.wall_a.is_empty()
	start = g.wall_start
	_items = g.wall_items
	_item_a = g.wall_item_a
	_item_ab = g.wall_item_ab
	_item_inv = g.wall_item_inv
	_item_rad = g.wall_item_radius
	_wall_ab = g.wall_ab
	_wall_inv_len2 = g.wall_inv_len2


## True when a ball of radius `r` at `p` overlaps a wall among list entries k0 .. k1;
## then the members above describe the deepest such contact.
func deepest(p: Vector2, r: float, k0: int, k1: int) -> bool:
	found = 0
	best = -1
	var best_depth := 0.0
	for k: int in range(k0, k1):
		var a: Vector2 = _item_a[k]
		var ab: Vector2 = _item_ab[k]
		var s: float = clampf((p - a).dot(ab) * _item_inv[k], 0.0, 1.0)
		var q: Vector2 = a + ab * s
		var lim: float = _item_rad[k] + r
		var d2: float = p.distance_squared_to(q)
		if d2 >= lim * lim:
			continue
		found += 1
		var depth: float = lim - sqrt(d2)
		if depth > best_depth or best < 0:
			best = _items[k]
			best_depth = depth
			best_s = s
			best_q = q
			best_lim = lim
	if best < 0:
		return false
	var d: Vector2 = p - best_q
	var dist2: float = d.length_squared()
	nrm = Vector2(0.0, -1.0)
	if dist2 > ContactMath.EPS * ContactMath.EPS:
		nrm = d / sqrt(dist2)
	elif _wall_inv_len2[best] > 0.0:
		var wall_ab: Vector2 = _wall_ab[best]
		nrm = Vector2(wall_ab.y, -wall_ab.x).normalized()
	return true
