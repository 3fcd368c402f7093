class_name WindmillChecks
extends RefCounted
## BoardValidator's checks of a pachinko board's windmills (WindmillSpec): sane numbers (a
## blade tip never outruns the fastest ball, as the physics' swept test needs), the sweep
## of the blades wholly inside the field (a ball's width clear of the ring and the launch
## rail), and no pin, pocket, bonus pocket or other windmill inside it. The blades pass
## through nothing, so an overlap is an error; a gap a ball could jam in is a warning.
## The file reader already refuses out-of-range numbers; these also cover boards built in
## code or in the editor.

const ERROR := BoardIssue.Severity.ERROR
const WARNING := BoardIssue.Severity.WARNING


## Appends the windmills' problems to `issues`.
static func check(level: BoardLevel, issues: Array[BoardIssue]) -> void:
	var sound: Array[int] = []
	for i in level.windmills.size():
		if _check_values(level, i, issues):
			sound.append(i)
	for i in sound:
		_check_inside_field(level, i, issues)
		_check_pins(level, i, issues)
		_check_pockets(level, i, issues)
	_check_pairs(level, sound, issues)


## "Windmill 3": the windmill's name for messages, by its stable id (ItemIds).
static func label(level: BoardLevel, index: int) -> String:
	return "Windmill %d" % ItemIds.of(level, "windmills", index)


static func _check_values(level: BoardLevel, i: int, issues: Array[BoardIssue]) -> bool:
	var spec := level.windmills[i]
	if spec == null:
		BoardIssue.add_to(
			issues, ERROR, "Windmill %d is empty." % (i + 1), level.ring_center, "bad_windmill"
		)
		return false
	var problem := _value_problem(level, spec)
	if not problem.is_empty():
		var text := "%s %s." % [label(level, i), problem]
		BoardIssue.add_to(issues, ERROR, text, _at(spec), "bad_windmill")
		return false
	if spec.free_spin and spec.friction == 0.0:
		var text := "%s spins free with no friction: once struck it never stops." % label(level, i)
		BoardIssue.add_to(issues, WARNING, text, spec.position, "windmill_no_friction")
	return true


# What is wrong with the spec's numbers ("" when nothing).
static func _value_problem(level: BoardLevel, spec: WindmillSpec) -> String:
	var lengths := WindmillSpec.LENGTH_RANGE
	var counts := WindmillSpec.BLADES_RANGE
	if not spec.position.is_finite() or not is_finite(spec.length):
		return "needs a finite position and blade length"
	if spec.blades < counts.x or spec.blades > counts.y:
		return "has %d blades; a wheel has %d to %d" % [spec.blades, counts.x, counts.y]
	if spec.length < lengths.x or spec.length > lengths.y:
		return (
			"has %s px blades; they must be %s to %s px long"
			% [_num(spec.length), _num(lengths.x), _num(lengths.y)]
		)
	if spec.free_spin:
		if not is_finite(spec.friction) or spec.friction < 0.0:
			return "needs a friction of 0 or more, got %s" % _num(spec.friction)
		return ""
	if not is_finite(spec.speed) or absf(spec.speed) > WindmillSpec.MAX_SPEED:
		return (
			"turns at %s degrees a second; at most %s"
			% [_num(spec.speed), _num(WindmillSpec.MAX_SPEED)]
		)
	var tuning := level.tuning if level.tuning != null else TuningPresets.for_kind(false)
	var top := tuning.max_speed
	if spec.tip_speed() > top:
		var fastest := rad_to_deg(top / spec.sweep_radius())
		return (
			(
				"moves its blade tips at %s px/s, faster than a ball can go (%s px/s): at most"
				+ " %s degrees a second"
			)
			% [_num(spec.tip_speed()), _num(top), _num(floorf(fastest))]
		)
	return ""


# The sweep must stay a ball's width inside the ring and clear of the launch rail.
static func _check_inside_field(level: BoardLevel, i: int, issues: Array[BoardIssue]) -> void:
	var spec := level.windmills[i]
	var room := level.ring_radius - maxf(level.rail_width, 0.0) - level.ball_radius * 2.0
	var out := spec.position.distance_to(level.ring_center) + spec.sweep_radius()
	if out > room:
		var text := (
			(
				"%s's blades reach %s px from the ring's centre; keep them within %s (a ball's"
				+ " width inside the ring and its launch rail)."
			)
			% [label(level, i), _num(out), _num(room)]
		)
		BoardIssue.add_covering(
			issues, ERROR, text, spec.position, "windmill_outside_field", _box(spec)
		)


static func _check_pins(level: BoardLevel, i: int, issues: Array[BoardIssue]) -> void:
	var spec := level.windmills[i]
	var reach := spec.sweep_radius() + level.pin_radius
	var jam := reach + level.ball_radius * 2.0
	for k in level.pins.size():
		var pin := level.pins[k]
		var d := pin.distance_to(spec.position)
		if d >= jam:
			continue
		var pin_name := "pin %d" % ItemIds.of(level, "pins", k)
		var pocket := level.pin_pocket[k] if k < level.pin_pocket.size() else -1
		if pocket >= 0:
			pin_name += " (pocket %d)" % ItemIds.of(level, "pockets", pocket)
		var area := BoardIssue.around(spec.position, spec.sweep_radius(), pin, level.pin_radius)
		if d < reach:
			var text := "%s's blades would sweep through %s." % [label(level, i), pin_name]
			BoardIssue.add_covering(issues, ERROR, text, pin, "windmill_hits_pin", area)
		else:
			var text := (
				"%s leaves a %.1f px gap to %s; a ball (%.0f px) would jam between them."
				% [label(level, i), d - reach, pin_name, level.ball_radius * 2.0]
			)
			BoardIssue.add_covering(issues, WARNING, text, pin, "windmill_pin_gap", area)


# No pocket's or bonus pocket's cup inside the sweep.
static func _check_pockets(level: BoardLevel, i: int, issues: Array[BoardIssue]) -> void:
	var spec := level.windmills[i]
	for p in level.pockets.size():
		var pocket := level.pockets[p]
		if pocket == null:
			continue
		var grow := level.pin_radius
		var top_left := pocket.position - Vector2(pocket.width * 0.5 + grow, grow)
		var cup := Rect2(top_left, Vector2(pocket.width + grow * 2.0, pocket.depth + grow * 2.0))
		if _circle_meets_rect(spec.position, spec.sweep_radius(), cup):
			var text := (
				"%s's blades would sweep into pocket %d."
				% [label(level, i), ItemIds.of(level, "pockets", p)]
			)
			BoardIssue.add_covering(
				issues, ERROR, text, pocket.position, "windmill_hits_pocket", cup.merge(_box(spec))
			)
	for b in level.bonus_pockets.size():
		var bonus := level.bonus_pockets[b]
		if bonus == null:
			continue
		var cup := BonusChecks.cup_rect(level, bonus)
		if _circle_meets_rect(spec.position, spec.sweep_radius(), cup):
			var text := (
				"%s's blades would sweep into %s." % [label(level, i), BonusChecks.label(level, b)]
			)
			BoardIssue.add_covering(
				issues, ERROR, text, bonus.position, "windmill_hits_pocket", cup.merge(_box(spec))
			)


static func _check_pairs(level: BoardLevel, sound: Array[int], issues: Array[BoardIssue]) -> void:
	for a in sound.size():
		for b in range(a + 1, sound.size()):
			var first := level.windmills[sound[a]]
			var second := level.windmills[sound[b]]
			var d := first.position.distance_to(second.position)
			var reach := first.sweep_radius() + second.sweep_radius()
			if d >= reach + level.ball_radius * 2.0:
				continue
			var names := (
				"Windmills %d and %d"
				% [
					ItemIds.of(level, "windmills", sound[a]),
					ItemIds.of(level, "windmills", sound[b])
				]
			)
			var area := _box(first).merge(_box(second))
			var mid := (first.position + second.position) * 0.5
			if d < reach:
				BoardIssue.add_covering(
					issues,
					ERROR,
					"%s overlap: their blades would cross." % names,
					mid,
					"windmills_overlap",
					area
				)
			else:
				var text := (
					"%s leave a %.1f px gap; a ball (%.0f px) would jam between them."
					% [names, d - reach, level.ball_radius * 2.0]
				)
				BoardIssue.add_covering(issues, WARNING, text, mid, "windmill_pair_gap", area)


static func _circle_meets_rect(c: Vector2, r: float, box: Rect2) -> bool:
	var q := Vector2(clampf(c.x, box.position.x, box.end.x), clampf(c.y, box.position.y, box.end.y))
	return q.distance_squared_to(c) < r * r


static func _box(spec: WindmillSpec) -> Rect2:
	var r := spec.sweep_radius()
	return Rect2(spec.position - Vector2(r, r), Vector2(r, r) * 2.0)


static func _at(spec: WindmillSpec) -> Vector2:
	return spec.position if spec.position.is_finite() else Vector2.ZERO


static func _num(number: float) -> String:
	return str(int(number)) if number == floorf(number) else "%.1f" % number
