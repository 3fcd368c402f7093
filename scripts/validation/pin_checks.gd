class_name PinChecks
extends RefCounted
## BoardValidator's pin checks for pachinko boards: every pin against the ring, the launch
## rail and its deflector, and pin pairs through a spatial hash (overlaps, gaps a ball would
## stick in), so a board with thousands of pins still validates in milliseconds.

const ERROR := BoardIssue.Severity.ERROR
const WARNING := BoardIssue.Severity.WARNING
## More pins than this in one grid cell (a ball's reach wide) cannot be a real layout.
const CROWDED_CELL_PINS := 48
## The pair check stops after this many overlap and gap warnings.
const MAX_PAIR_ISSUES := 200


## Each pin against its pocket, the ring, the launch rail and the rail's deflector.
static func check_pins(level: BoardLevel, issues: Array[BoardIssue]) -> void:
	var c := level.ring_center
	var inside := level.ring_radius - level.pin_radius
	var guide := LaunchRail.guide_radius(level)
	var guide_clear := guide - LaunchRail.GUIDE_WALL_RADIUS - level.pin_radius
	var rail_low := minf(level.rail_start_deg, level.rail_end_deg)
	var rail_high := maxf(level.rail_start_deg, level.rail_end_deg)
	for i in level.pins.size():
		var p := level.pins[i]
		if not p.is_finite():
			BoardIssue.add_to(
				issues,
				ERROR,
				"%s has a position that is not a number." % _pin(level, i),
				c,
				"not_finite"
			)
			continue
		_check_pin_owner(level, i, issues)
		var d := p.distance_to(c)
		if ItemIds.is_rim_pin(level, i) and not where_outside(level, p).is_empty():
			continue  # one error for the whole pocket (PachinkoChecks), not one per rim pin
		if d > inside:
			BoardIssue.add_to(
				issues,
				ERROR,
				"%s at (%.0f, %.0f) is outside the ring." % [_pin(level, i), p.x, p.y],
				p,
				"pin_outside_ring"
			)
			continue
		var in_rail_arc := angle_in(rad_to_deg((p - c).angle()), rail_low, rail_high)
		if in_rail_arc and d > guide_clear:
			BoardIssue.add_to(
				issues,
				ERROR,
				"%s at (%.0f, %.0f) sits in the launch rail." % [_pin(level, i), p.x, p.y],
				p,
				"pin_in_rail"
			)
			continue
		# Rim pins of a pocket stand close to walls on purpose: only free pins trap balls.
		if level.pin_pocket[i] < 0:
			var edge_gap := (guide_clear if in_rail_arc else inside) - d
			_check_pin_gaps(level, i, edge_gap, in_rail_arc, issues)


## Where a pin at `p` leaves the field: "outside the ring", "in the launch rail", or "".
static func where_outside(level: BoardLevel, p: Vector2) -> String:
	var c := level.ring_center
	var d := p.distance_to(c)
	if d > level.ring_radius - level.pin_radius:
		return "outside the ring"
	var guide := LaunchRail.guide_radius(level)
	var guide_clear := guide - LaunchRail.GUIDE_WALL_RADIUS - level.pin_radius
	var low := minf(level.rail_start_deg, level.rail_end_deg)
	var high := maxf(level.rail_start_deg, level.rail_end_deg)
	if d > guide_clear and angle_in(rad_to_deg((p - c).angle()), low, high):
		return "in the launch rail"
	return ""


# Pin i's pocket must exist, and a special pin must belong to one.
static func _check_pin_owner(level: BoardLevel, i: int, issues: Array[BoardIssue]) -> void:
	var owner := level.pin_pocket[i]
	if owner < -1 or owner >= level.pockets.size():
		BoardIssue.add_to(
			issues,
			ERROR,
			"%s belongs to pocket %d, which does not exist." % [_pin(level, i), owner + 1],
			level.pins[i],
			"bad_pin_pocket"
		)
	elif level.pin_special[i] != 0 and owner < 0:
		BoardIssue.add_to(
			issues,
			ERROR,
			"%s is a special pin but belongs to no pocket." % _pin(level, i),
			level.pins[i],
			"special_without_pocket"
		)


# Warns when free pin i leaves a gap narrower than a ball to the rail's deflector, or else to
# the edge it faces (`edge_gap` away: the rail's guide inside the rail arc, the ring outside).
static func _check_pin_gaps(
	level: BoardLevel, i: int, edge_gap: float, in_rail_arc: bool, issues: Array[BoardIssue]
) -> void:
	var p := level.pins[i]
	var diameter := level.ball_radius * 2.0
	var deflector_gap := _deflector_gap(level, p)
	if deflector_gap < diameter:
		(
			BoardIssue
			. add_to(
				issues,
				WARNING,
				(
					"%s leaves a %.1f px gap to the rail's deflector; a ball (%.0f px) would stick there."
					% [_pin(level, i), maxf(deflector_gap, 0.0), diameter]
				),
				p,
				"narrow_gap_rail"
			)
		)
		return
	if edge_gap < diameter:
		var code := "narrow_gap_rail" if in_rail_arc else "narrow_gap_ring"
		var what := "the rail's guide" if in_rail_arc else "the ring"
		BoardIssue.add_to(
			issues,
			WARNING,
			(
				"%s leaves a %.1f px gap to %s; a ball (%.0f px) would stick there."
				% [_pin(level, i), maxf(edge_gap, 0.0), what, diameter]
			),
			p,
			code
		)


static func check_pin_pairs(level: BoardLevel, issues: Array[BoardIssue]) -> void:
	var pins := level.pins
	var touch := 2.0 * level.pin_radius
	var reach := touch + 2.0 * level.ball_radius
	var grid := PointGrid.new(pins, maxf(reach, 1.0))
	if _crowded(level, grid, issues):
		return
	var pair_issues_before := issues.size()
	var touch2 := touch * touch - 1e-6
	var reach2 := reach * reach
	for i in pins.size():
		var p := pins[i]
		if not p.is_finite():
			continue
		if issues.size() - pair_issues_before >= MAX_PAIR_ISSUES:
			BoardIssue.add_to(
				issues,
				WARNING,
				"More pins overlap or leave narrow gaps; fix these %d first." % MAX_PAIR_ISSUES,
				p,
				"narrow_gap"
			)
			return
		for j in grid.near(p):
			if j <= i:
				continue
			var d2 := p.distance_squared_to(pins[j])
			if d2 >= reach2:
				continue
			var mid := (p + pins[j]) * 0.5
			if d2 < touch2:
				BoardIssue.add_covering(
					issues,
					WARNING,
					"%s overlap." % _pins(level, i, j),
					mid,
					"pin_overlap",
					BoardIssue.around(p, level.pin_radius, pins[j], level.pin_radius)
				)
			elif level.pin_pocket[i] < 0 or level.pin_pocket[i] != level.pin_pocket[j]:
				# Rim pins of one pocket are meant to be closer than a ball.
				var gap := sqrt(d2) - touch
				BoardIssue.add_covering(
					issues,
					WARNING,
					(
						"%s leave a %.1f px gap; a ball (%.0f px) would stick in it."
						% [_pins(level, i, j), gap, reach - touch]
					),
					mid,
					"narrow_gap",
					BoardIssue.around(p, level.pin_radius, pins[j], level.pin_radius)
				)


# A spot holding far more pins than fit there without overlapping is a broken board, and
# checking its pins pair by pair would take minutes: refuse it with one error instead.
static func _crowded(level: BoardLevel, grid: PointGrid, issues: Array[BoardIssue]) -> bool:
	var cell := grid.cell
	for key: Vector2i in grid.buckets:
		var bucket: PackedInt32Array = grid.buckets[key]
		if bucket.size() > CROWDED_CELL_PINS:
			var at := (Vector2(key) + Vector2(0.5, 0.5)) * cell
			(
				BoardIssue
				. add_to(
					issues,
					ERROR,
					(
						"%d pins crowd into one %.0f px spot near (%.0f, %.0f); pins that close overlap."
						% [bucket.size(), cell, at.x, at.y]
					),
					level.pins[bucket[0]],
					"pin_overlap"
				)
			)
			return true
	return false


# Gap between pin `p` and the deflector past the rail's end (surface to surface).
static func _deflector_gap(level: BoardLevel, p: Vector2) -> float:
	var ends := LaunchRail.deflector(level)
	var nearest := Geometry2D.get_closest_point_to_segment(p, ends[0], ends[1])
	return p.distance_to(nearest) - LaunchRail.GUIDE_WALL_RADIUS - level.pin_radius


## True when angle `deg` lies within [low, high] (degrees, any winding).
static func angle_in(deg: float, low: float, high: float) -> bool:
	return fposmod(deg - low, 360.0) <= high - low


## True when the arcs [a0, a1] and [b0, b1] (degrees) share any angle.
static func arcs_overlap(a0: float, a1: float, b0: float, b1: float) -> bool:
	return (
		angle_in(a0, b0, b1) or angle_in(a1, b0, b1) or angle_in(b0, a0, a1) or angle_in(b1, a0, a1)
	)


# "Pin 17", or "A pin of pocket 2's rim" (rim pins have no id of their own).
static func _pin(level: BoardLevel, i: int) -> String:
	var label := ItemIds.pin_label(level, i)
	return label.left(1).to_upper() + label.substr(1)


# "Pins 3 and 4", or "Pin 3 and a pin of pocket 2's rim".
static func _pins(level: BoardLevel, i: int, j: int) -> String:
	if not ItemIds.is_rim_pin(level, i) and not ItemIds.is_rim_pin(level, j):
		return "Pins %d and %d" % [ItemIds.of(level, "pins", i), ItemIds.of(level, "pins", j)]
	return "%s and %s" % [_pin(level, i), ItemIds.pin_label(level, j)]
