class_name PachinkoChecks
extends RefCounted
## BoardValidator's pachinko checks: ring, rail, gutter, cup and pockets; the pins
## themselves are checked by pin_checks.gd, the windmills by windmill_checks.gd.

const ERROR := BoardIssue.Severity.ERROR
const WARNING := BoardIssue.Severity.WARNING
## Extra width the launch channel needs beyond the ball and the guide wall, in pixels.
const RAIL_CLEARANCE := 2.0


static func check(level: BoardLevel, issues: Array[BoardIssue]) -> void:
	if not _check_shape(level, issues):
		return
	_check_rail_and_gutter(level, issues)
	PinChecks.check_pins(level, issues)
	_check_pockets(level, issues)
	PinChecks.check_pin_pairs(level, issues)
	BonusChecks.check(level, issues)
	WindmillChecks.check(level, issues)


# Ring, pin radius, array lengths and pocket specs: what every later check relies on.
# Every part is checked (and reported) even when an earlier one failed.
static func _check_shape(level: BoardLevel, issues: Array[BoardIssue]) -> bool:
	var ring_ok := _check_ring(level, issues)
	var pins_ok := _check_pin_lists(level, issues)
	var pockets_ok := _check_pocket_specs(level, issues)
	_check_cup(level, issues)
	return ring_ok and pins_ok and pockets_ok


# A finite ring big enough for four balls (an error otherwise); poking out of the board
# is only a warning.
static func _check_ring(level: BoardLevel, issues: Array[BoardIssue]) -> bool:
	var c := level.ring_center
	var r := level.ring_radius
	if not c.is_finite() or not is_finite(r) or r <= level.ball_radius * 4.0:
		BoardIssue.add_to(
			issues,
			ERROR,
			"The ring needs a finite centre and a radius above four balls (got %s, %s)." % [c, r],
			Vector2.ZERO,
			"bad_ring"
		)
		return false
	if (
		c.x - r < -0.5
		or c.y - r < -0.5
		or c.x + r > level.size.x + 0.5
		or c.y + r > level.size.y + 0.5
	):
		BoardIssue.add_covering(
			issues,
			WARNING,
			"The ring pokes out of the board's %s area." % level.size,
			c,
			"ring_outside_board",
			BoardIssue.around(c, r, c, r)
		)
	return true


# A positive pin radius, and one pocket entry and one special flag per pin.
static func _check_pin_lists(level: BoardLevel, issues: Array[BoardIssue]) -> bool:
	var ok := true
	var c := level.ring_center
	if not is_finite(level.pin_radius) or level.pin_radius <= 0.0:
		BoardIssue.add_to(
			issues,
			ERROR,
			"The pin radius must be positive, got %s." % level.pin_radius,
			c,
			"bad_pin_radius"
		)
		ok = false
	if (
		level.pin_pocket.size() != level.pins.size()
		or level.pin_special.size() != level.pins.size()
	):
		BoardIssue.add_to(
			issues,
			ERROR,
			(
				"The pin lists disagree: %d pins, %d pocket entries, %d special flags."
				% [level.pins.size(), level.pin_pocket.size(), level.pin_special.size()]
			),
			c,
			"pin_arrays_mismatch"
		)
		ok = false
	return ok


# Each pocket: present, with a finite position and positive size (errors that stop the
# later checks), a payout that is not negative, deep enough for its rim.
static func _check_pocket_specs(level: BoardLevel, issues: Array[BoardIssue]) -> bool:
	var ok := true
	var c := level.ring_center
	for i in level.pockets.size():
		var spec: PocketSpec = level.pockets[i]
		if spec == null:
			BoardIssue.add_to(
				issues,
				ERROR,
				"Pocket %d is empty." % ItemIds.of(level, "pockets", i),
				c,
				"bad_pocket"
			)
			ok = false
		elif (
			not spec.position.is_finite()
			or not is_finite(spec.width)
			or not is_finite(spec.depth)
			or spec.width <= 0.0
			or spec.depth <= 0.0
		):
			BoardIssue.add_to(
				issues,
				ERROR,
				(
					"Pocket %d needs a finite position and a positive width and depth."
					% ItemIds.of(level, "pockets", i)
				),
				c,
				"bad_pocket"
			)
			ok = false
		elif spec.payout < 0:
			BoardIssue.add_to(
				issues,
				ERROR,
				(
					"Pocket %d pays %d balls; a payout cannot be negative."
					% [ItemIds.of(level, "pockets", i), spec.payout]
				),
				spec.position,
				"bad_pocket"
			)
		elif spec.depth < spec.width * 0.5:
			BoardIssue.add_to(
				issues,
				WARNING,
				(
					"Pocket %d is shallower than half its width; its rim cannot be stamped."
					% ItemIds.of(level, "pockets", i)
				),
				spec.position,
				"pocket_shallow"
			)
	return ok


static func _check_cup(level: BoardLevel, issues: Array[BoardIssue]) -> void:
	if level.cup_start_balls < 1:
		BoardIssue.add_to(
			issues,
			ERROR,
			"The cup must start with at least one ball (got %d)." % level.cup_start_balls,
			level.ring_center,
			"bad_cup"
		)


static func _check_rail_and_gutter(level: BoardLevel, issues: Array[BoardIssue]) -> void:
	var c := level.ring_center
	var need := 2.0 * level.ball_radius + LaunchRail.GUIDE_WALL_RADIUS * 2.0 + RAIL_CLEARANCE
	if (
		not is_finite(level.rail_width)
		or level.rail_width < need
		or level.rail_width > level.ring_radius * 0.5
	):
		BoardIssue.add_to(
			issues,
			ERROR,
			(
				"The launch rail must be between %.1f and %.1f px wide, got %s."
				% [need, level.ring_radius * 0.5, level.rail_width]
			),
			c,
			"bad_rail"
		)
	var sweep := absf(level.rail_end_deg - level.rail_start_deg)
	if (
		not is_finite(level.rail_start_deg)
		or not is_finite(level.rail_end_deg)
		or sweep < 10.0
		or sweep > 350.0
	):
		BoardIssue.add_to(
			issues,
			ERROR,
			(
				"The launch rail must sweep between 10° and 350°, got %s° to %s°."
				% [level.rail_start_deg, level.rail_end_deg]
			),
			c,
			"bad_rail"
		)
	var g0 := level.gutter_start_deg
	var g1 := level.gutter_end_deg
	if not is_finite(g0) or not is_finite(g1) or g1 <= g0 or g1 - g0 > 180.0:
		(
			BoardIssue
			. add_to(
				issues,
				ERROR,
				(
					"The gutter must run from a start angle to a larger end angle within 180°, got %s° to %s°."
					% [g0, g1]
				),
				c,
				"bad_gutter"
			)
		)
	elif level.gutter_bounces < 1:
		BoardIssue.add_to(
			issues,
			ERROR,
			"The gutter needs at least one bounce (got %d)." % level.gutter_bounces,
			c,
			"bad_gutter"
		)
	elif PinChecks.arcs_overlap(
		g0,
		g1,
		minf(level.rail_start_deg, level.rail_end_deg),
		maxf(level.rail_start_deg, level.rail_end_deg)
	):
		var mid := deg_to_rad((g0 + g1) * 0.5)
		BoardIssue.add_to(
			issues,
			WARNING,
			"The gutter overlaps the launch rail: balls rolling back would drain.",
			c + Vector2(cos(mid), sin(mid)) * level.ring_radius,
			"gutter_on_rail"
		)


static func _check_pockets(level: BoardLevel, issues: Array[BoardIssue]) -> void:
	var specials := PackedInt32Array()
	specials.resize(level.pockets.size())
	for i in level.pins.size():
		var owner := level.pin_pocket[i]
		if owner >= 0 and owner < specials.size() and level.pin_special[i] != 0:
			specials[owner] += 1
	if level.pockets.is_empty() and level.bonus_pockets.is_empty():
		BoardIssue.add_to(
			issues,
			WARNING,
			"The board has no pockets, so no shot can win balls back.",
			level.ring_center,
			"no_pockets"
		)
	var clear_ring := level.ring_radius - level.ball_radius
	var leaving := _rims_leaving_field(level)
	for k in level.pockets.size():
		var spec: PocketSpec = level.pockets[k]
		if leaving.has(k):
			var at: Vector2 = leaving[k][0]
			BoardIssue.add_to(
				issues,
				ERROR,
				"Pocket %d's rim is %s." % [ItemIds.of(level, "pockets", k), leaving[k][1]],
				at,
				"pocket_outside_field"
			)
			continue
		if specials[k] == 0:
			BoardIssue.add_to(
				issues,
				ERROR,
				(
					"Pocket %d has no special pin, so it can never pay."
					% ItemIds.of(level, "pockets", k)
				),
				spec.position,
				"pocket_without_special"
			)
		var clear_mouth := spec.width - 2.0 * level.pin_radius
		if clear_mouth < level.ball_radius * 2.0:
			BoardIssue.add_to(
				issues,
				WARNING,
				(
					"Pocket %d's mouth is %.1f px wide; a ball (%.0f px) cannot enter."
					% [ItemIds.of(level, "pockets", k), clear_mouth, level.ball_radius * 2.0]
				),
				spec.position,
				"pocket_unreachable"
			)
		elif spec.position.distance_to(level.ring_center) > clear_ring - spec.width:
			BoardIssue.add_to(
				issues,
				WARNING,
				(
					"Pocket %d's mouth is outside the field; no ball can enter it."
					% ItemIds.of(level, "pockets", k)
				),
				spec.position,
				"pocket_unreachable"
			)
		else:
			var blocker := _pin_in_mouth(level, k)
			if blocker >= 0:
				BoardIssue.add_to(
					issues,
					WARNING,
					(
						"%s blocks the mouth of pocket %d; no ball can enter."
						% [_pin_name(level, blocker), ItemIds.of(level, "pockets", k)]
					),
					level.pins[blocker],
					"pocket_unreachable"
				)


# Pocket index -> [where, what] for each pocket with a rim pin off the field (the first one).
static func _rims_leaving_field(level: BoardLevel) -> Dictionary:
	var leaving := {}
	for i in level.pins.size():
		var owner := level.pin_pocket[i]
		if owner < 0 or leaving.has(owner) or not level.pins[i].is_finite():
			continue
		var where := PinChecks.where_outside(level, level.pins[i])
		if not where.is_empty():
			leaving[owner] = [level.pins[i], where]
	return leaving


static func _pin_name(level: BoardLevel, i: int) -> String:
	var label := ItemIds.pin_label(level, i)
	return label.left(1).to_upper() + label.substr(1)


# A pin (not of pocket k) inside pocket k's mouth opening or cup, else -1.
static func _pin_in_mouth(level: BoardLevel, k: int) -> int:
	var spec: PocketSpec = level.pockets[k]
	var half := spec.width * 0.5 - level.pin_radius
	var inner := Rect2(
		spec.position.x - half, spec.position.y - level.ball_radius, half * 2.0, spec.depth
	)
	for i in level.pins.size():
		if level.pin_pocket[i] != k and inner.has_point(level.pins[i]):
			return i
	return -1
