class_name BonusGeometry
extends RefCounted
## The shapes of a board's bonus pockets, computed from the level alone so the world
## factory, the rules and the views agree on them without sharing state.
##
## Every bonus pocket is a PocketStamp cup whose pins are added after the level's own pins,
## tagged with pocket id `level.pockets.size() + index` (its special pin catches). Its moving
## parts: an attacker's lid across the mouth is two capsule walls with a low ridge, added to
## the world before any other wall (on while closed), so wall `k` of `wall_plan()` is world
## wall `k`; a tulip's two wings are the petals of a world gate (BallWorld.add_gate), gate
## `k` being the k-th tulip, hinged at the mouth's corners: upright while shut, leaning
## out while open, swinging between the two in TULIP_SWING_SECONDS.

enum Part { LID }

## Capsule radius of a lid or a wing, px.
const PART_RADIUS := 2.5
## A shut lid's rise from each end to its ridge, per pixel across (a gentle roof).
const LID_SLOPE := 0.2
## Half the size of the reels' window high in the field (boards with a start pocket).
const REEL_HALF := Vector2(54.0, 22.0)
## The window's frame: capsules this thick just outside it, its top a low roof rising
## REEL_ROOF px to the middle so balls roll off instead of resting on it.
const REEL_FRAME_RADIUS := 3.0
const REEL_ROOF := 24.0
## A tulip's wing length as a share of the mouth width.
const WING_SHARE := 0.75
## An open wing leans out this far from upright, radians (about 50 degrees).
const WING_OPEN_ANGLE := 0.87
## Seconds a tulip's wings take to swing fully open or shut.
const TULIP_SWING_SECONDS := 0.2


## The pocket id the world reports for bonus pocket `index` of `level`.
static func pocket_id(level: BoardLevel, index: int) -> int:
	return level.pockets.size() + index


## The bonus pocket index for a world pocket id, or -1 for one of the level's own pockets.
static func bonus_index(level: BoardLevel, world_pocket_id: int) -> int:
	var index := world_pocket_id - level.pockets.size()
	return index if index >= 0 and index < level.bonus_pockets.size() else -1


## True when `level` has a start pocket (and so the reels).
static func has_reels(level: BoardLevel) -> bool:
	for spec in level.bonus_pockets:
		if spec != null and spec.role == BonusPocketSpec.Role.START:
			return true
	return false


## The centre of the reels' window on `level`: high in the middle of the field.
static func reel_spot(level: BoardLevel) -> Vector2:
	return level.ring_center + Vector2(0.0, -level.ring_radius * 0.6)


## The reels' window, board pixels.
static func reel_window(level: BoardLevel) -> Rect2:
	return Rect2(reel_spot(level) - REEL_HALF, REEL_HALF * 2.0)


## The reels' frame as capsules [a, b, ...] (pairs of ends): the sides, the bottom and a
## low roof; none on a board without reels. A solid centre piece as on a real machine:
## balls bounce off it and never pass over the numbers.
static func reel_frame(level: BoardLevel) -> PackedVector2Array:
	if not has_reels(level):
		return PackedVector2Array()
	var box := reel_window(level).grow(REEL_FRAME_RADIUS)
	var ridge := Vector2(box.get_center().x, box.position.y - REEL_ROOF)
	var top_left := box.position
	var top_right := Vector2(box.end.x, box.position.y)
	var bottom_left := Vector2(box.position.x, box.end.y)
	return PackedVector2Array(
		[
			top_left,
			ridge,
			ridge,
			top_right,
			top_right,
			box.end,
			box.end,
			bottom_left,
			bottom_left,
			top_left,
		]
	)


## The attackers' lids, in world wall order: [{"item": index, "part": Part, "a", "b"}].
static func wall_plan(level: BoardLevel) -> Array[Dictionary]:
	var plan: Array[Dictionary] = []
	for i in level.bonus_pockets.size():
		var spec := level.bonus_pockets[i]
		if spec == null or spec.role != BonusPocketSpec.Role.ATTACKER:
			continue
		# Two halves meeting in a low ridge, so balls roll off a shut lid instead of
		# resting on it until the watcher nudges them.
		var half := spec.width * 0.5
		var ridge := lid_ridge(spec)
		plan.append(_part(i, Part.LID, spec.position + Vector2(-half, 0.0), ridge))
		plan.append(_part(i, Part.LID, ridge, spec.position + Vector2(half, 0.0)))
	return plan


## The tulips' wings, in world gate order (gate k is the k-th tulip; two petals each, left
## then right): [{"item": index, "hinge": Vector2, "length": float, "shut": angle,
## "open": angle}], angles in radians, y down.
static func petal_plan(level: BoardLevel) -> Array[Dictionary]:
	var plan: Array[Dictionary] = []
	for i in level.bonus_pockets.size():
		var spec := level.bonus_pockets[i]
		if spec == null or spec.role != BonusPocketSpec.Role.TULIP:
			continue
		for side: float in [-1.0, 1.0]:
			var upright := -PI * 0.5
			(
				plan
				. append(
					{
						"item": i,
						"hinge": spec.position + Vector2(side * spec.width * 0.5, 0.0),
						"length": spec.width * WING_SHARE,
						"shut": upright,
						"open": upright + side * WING_OPEN_ANGLE,
					}
				)
			)
	return plan


## The tip of a petal of petal_plan() when its tulip is `openness` open (0 shut, 1 open).
static func petal_tip(petal: Dictionary, openness: float) -> Vector2:
	var shut: float = petal["shut"]
	var open: float = petal["open"]
	var length: float = petal["length"]
	var hinge: Vector2 = petal["hinge"]
	return hinge + Vector2.from_angle(lerpf(shut, open, openness)) * length


## The world gate of bonus pocket `index` of `level` (its place among the tulips), or -1
## for a pocket that is not a tulip.
static func tulip_gate(level: BoardLevel, index: int) -> int:
	if index < 0 or index >= level.bonus_pockets.size():
		return -1
	var spec := level.bonus_pockets[index]
	if spec == null or spec.role != BonusPocketSpec.Role.TULIP:
		return -1
	var gate := 0
	for k in index:
		var other := level.bonus_pockets[k]
		if other != null and other.role == BonusPocketSpec.Role.TULIP:
			gate += 1
	return gate


## The top of a shut attacker lid: its two halves rise to this point above the mouth's
## middle.
static func lid_ridge(spec: BonusPocketSpec) -> Vector2:
	return spec.position + Vector2(0.0, -spec.width * LID_SLOPE * 0.5)


## True when a part is solid while its pocket is `open` (a lid is solid while shut).
static func part_solid(_lid: Part, open: bool) -> bool:
	return not open


## Adds the attackers' lids to `world`, closed; call before any other wall.
static func add_walls(world: BallWorld, level: BoardLevel) -> void:
	for entry in wall_plan(level):
		var a: Vector2 = entry["a"]
		var b: Vector2 = entry["b"]
		world.shapes.add_wall(a, b, PART_RADIUS)


## Adds each tulip's wings to `world` as a shut gate of two petals (petal_plan's order), of
## the pins' material `min_speed_x`.
static func add_gates(world: BallWorld, level: BoardLevel, min_speed_x: float) -> void:
	var gate := -1
	var item := -1
	for petal in petal_plan(level):
		if petal["item"] != item:
			item = petal["item"]
			gate = world.shapes.add_gate(TULIP_SWING_SECONDS)
		var hinge: Vector2 = petal["hinge"]
		var length: float = petal["length"]
		var shut: float = petal["shut"]
		var open: float = petal["open"]
		world.shapes.add_petal(gate, hinge, length, PART_RADIUS, shut, open, min_speed_x)


## Adds every bonus pocket's rim and catching pin to `world` (after the level's pins).
static func add_pins(world: BallWorld, level: BoardLevel, min_speed_x: float) -> void:
	for i in level.bonus_pockets.size():
		var spec := level.bonus_pockets[i]
		if spec == null:
			continue
		var stamp := rim_pins(level, spec)
		for k in stamp.size():
			var special := k == stamp.size() - 1
			world.shapes.add_pin(
				stamp[k], level.pin_radius, pocket_id(level, i), special, min_speed_x
			)


## The rim pins of one bonus pocket, the catching pin last (PocketStamp's shape).
static func rim_pins(level: BoardLevel, spec: BonusPocketSpec) -> PackedVector2Array:
	return PocketStamp.pins_for(spec.as_pocket(), level.pin_radius, level.ball_radius)


## Every pocket the world reports, by world pocket id: the level's pockets, then the bonus
## pockets, each as {"payout", "position", "role"} ("pocket", "start_pocket", "attacker",
## "tulip"). For counting catches without the rules (the play analysis).
static func world_pockets(level: BoardLevel) -> Array[Dictionary]:
	var out: Array[Dictionary] = []
	for spec in level.pockets:
		var at := spec.position if spec != null else Vector2.ZERO
		out.append(
			{
				"payout": maxi(spec.payout, 0) if spec != null else 0,
				"position": at,
				"role": "pocket"
			}
		)
	for spec in level.bonus_pockets:
		var at := spec.position if spec != null else Vector2.ZERO
		var pays := maxi(spec.payout, 0) if spec != null else 0
		out.append(
			{"payout": pays, "position": at, "role": spec.role_key() if spec != null else ""}
		)
	return out


## The lowest catching pin of the bonus pockets (its y), or -INF for none.
static func lowest_catch_y(level: BoardLevel) -> float:
	var lowest := -INF
	for spec in level.bonus_pockets:
		if spec != null:
			lowest = maxf(lowest, spec.position.y + spec.depth)
	return lowest


static func _part(item: int, part: Part, a: Vector2, b: Vector2) -> Dictionary:
	return {"item": item, "part": part, "a": a, "b": b}
