class_name PocketStamp
extends RefCounted
## The pins that make a pachinko pocket: a U-shaped rim of pins close enough that a ball
## cannot slip between them, with the special (catching) pin at the very bottom.
##
## Shape: two straight sides at `position.x ± width / 2` running down from the mouth, joined
## by a half circle of radius `width / 2` whose lowest point, `position + (0, depth)`, holds
## the special pin. A ball that drops into the mouth rolls to the bottom and touches it.

## Rim pin spacing as a fraction of the widest gap that still stops a ball.
const SPACING_SAFETY := 0.6
## A board pocket's pins sit on the board file's coordinate grid (BoardTextWriter.PRECISION),
## so a pocket stamped in the editor and the same pocket read from its file are the same pins.
const PRECISION := 0.01


## Centre distance between neighbouring rim pins: comfortably below the distance at which a
## ball (radius `ball_radius`) would fit between two pins (radius `pin_radius`).
static func rim_spacing(pin_radius: float, ball_radius: float) -> float:
	return 2.0 * (pin_radius + ball_radius) * SPACING_SAFETY


## Where the special pin of `spec` sits.
static func special_position(spec: PocketSpec) -> Vector2:
	return spec.position + Vector2(0.0, spec.depth)


## The rim pins of `spec`, from the top of the left side down, round the bottom and up the
## right side. The special pin is the last point and is not repeated in the rim.
static func pins_for(spec: PocketSpec, pin_radius: float, ball_radius: float) -> PackedVector2Array:
	var points := PackedVector2Array()
	var half := spec.width * 0.5
	if half <= 0.0 or spec.depth < half:
		# Too shallow for a half-circle bottom: a flat-bottomed cup is not supported.
		points.append(special_position(spec))
		return points
	var spacing := rim_spacing(pin_radius, ball_radius)
	var bottom_center := spec.position + Vector2(0.0, spec.depth - half)
	var side_length := spec.depth - half
	var side_steps := maxi(1, ceili(side_length / spacing)) if side_length > 0.0 else 0
	var arc_steps := maxi(2, ceili(PI * half / spacing))
	if arc_steps % 2 == 1:
		arc_steps += 1  # even, so the bottom point is an arc vertex
	# Left side, downwards (the arc's first point closes it).
	for i in side_steps:
		var t := float(i) / float(side_steps)
		points.append(spec.position + Vector2(-half, side_length * t))
	# Half circle from the left (angle 180°) through the bottom (90°) to the right (0°).
	@warning_ignore("integer_division")  # arc_steps is even: the bottom vertex's index
	var bottom_index := arc_steps / 2
	for i in arc_steps + 1:
		if i == bottom_index:
			continue  # the special pin goes last
		var angle := PI - PI * float(i) / float(arc_steps)
		points.append(bottom_center + Vector2(cos(angle), sin(angle)) * half)
	# Right side, upwards.
	for i in range(side_steps - 1, -1, -1):
		var t := float(i) / float(side_steps)
		points.append(spec.position + Vector2(half, side_length * t))
	points.append(special_position(spec))
	return points


## The pins a board pocket stamps: `pins_for` on the file's coordinate grid (PRECISION). The
## board file stores only the pocket, so these are the pins the game builds from it.
static func rim_pins(spec: PocketSpec, pin_radius: float, ball_radius: float) -> PackedVector2Array:
	var points := pins_for(spec, pin_radius, ball_radius)
	for i in points.size():
		points[i] = Vector2(snappedf(points[i].x, PRECISION), snappedf(points[i].y, PRECISION))
	return points


## Replaces the pins of pocket `index` in `level` with a fresh stamp of its spec: removes
## every pin that belonged to the pocket and appends the new rim and special pin.
static func apply(level: BoardLevel, index: int) -> void:
	if index < 0 or index >= level.pockets.size():
		push_error("PocketStamp.apply: no pocket %d (board has %d)" % [index, level.pockets.size()])
		return
	remove(level, index, false)
	var spec: PocketSpec = level.pockets[index]
	var stamp := rim_pins(spec, level.pin_radius, level.ball_radius)
	var pins := level.pins
	var owners := level.pin_pocket
	var special := level.pin_special
	for i in stamp.size():
		pins.append(stamp[i])
		owners.append(index)
		special.append(1 if i == stamp.size() - 1 else 0)
	level.pins = pins
	level.pin_pocket = owners
	level.pin_special = special


## Removes the pins of pocket `index` from `level`. With `drop_spec`, also removes the pocket
## itself and renumbers the pins of later pockets.
static func remove(level: BoardLevel, index: int, drop_spec: bool = true) -> void:
	var pins := PackedVector2Array()
	var owners := PackedInt32Array()
	var special := PackedByteArray()
	for i in level.pins.size():
		var owner := level.pin_pocket[i] if i < level.pin_pocket.size() else -1
		if owner == index:
			continue
		if drop_spec and owner > index:
			owner -= 1
		pins.append(level.pins[i])
		owners.append(owner)
		special.append(level.pin_special[i] if i < level.pin_special.size() else 0)
	level.pins = pins
	level.pin_pocket = owners
	level.pin_special = special
	if drop_spec and index >= 0 and index < level.pockets.size():
		var pockets := level.pockets.duplicate()
		pockets.remove_at(index)
		level.pockets = pockets
