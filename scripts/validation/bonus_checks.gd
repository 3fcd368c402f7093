class_name BonusChecks
extends RefCounted
## BoardValidator's checks of the bonus layer (BonusPocketSpec): every value in range, every
## cup deep enough to stamp and wholly inside the ring with its lid or wings, no two cups
## overlapping, no field pin inside a cup, and attackers that a start pocket can open.
## The file reader already refuses out-of-range numbers; these checks also cover boards
## built in code or in the editor.

const ERROR := BoardIssue.Severity.ERROR
const WARNING := BoardIssue.Severity.WARNING
## Payout, symbols per reel, attacker seconds and catches: the file reader's ranges.
const PAYOUT := BoardRanges.BONUS_PAYOUT
const SYMBOLS := BoardRanges.BONUS_SYMBOLS
const OPEN_SECONDS := BoardRanges.BONUS_OPEN_SECONDS
const CATCHES := BoardRanges.BONUS_OPEN_CATCHES


## Appends the bonus layer's problems to `issues`.
static func check(level: BoardLevel, issues: Array[BoardIssue]) -> void:
	var sound: Array[int] = []
	for i in level.bonus_pockets.size():
		if _check_values(level, i, issues):
			sound.append(i)
	for i in sound:
		_check_inside_ring(level, i, issues)
		_check_field_pins(level, i, issues)
	_check_overlaps(level, sound, issues)
	_check_roles(level, issues)


## The cup's box (rim pins included), board pixels.
static func cup_rect(level: BoardLevel, spec: BonusPocketSpec) -> Rect2:
	var grow := maxf(level.pin_radius, 0.0)
	var top_left := spec.position - Vector2(spec.width * 0.5 + grow, grow)
	return Rect2(top_left, Vector2(spec.width + grow * 2.0, spec.depth + grow * 2.0))


## "Start pocket 2", "Tulip 1": the pocket's name for messages, by its stable id (ItemIds),
## the number the board file and the editor use for it.
static func label(level: BoardLevel, index: int) -> String:
	var spec := level.bonus_pockets[index]
	return "%s %d" % [spec.role_name(), ItemIds.of_bonus(level, index)]


static func _check_values(level: BoardLevel, i: int, issues: Array[BoardIssue]) -> bool:
	var spec := level.bonus_pockets[i]
	var at := level.ring_center
	if spec == null:
		BoardIssue.add_to(issues, ERROR, "Bonus pocket %d is empty." % (i + 1), at, "bad_bonus")
		return false
	var name := label(level, i)
	var problem := ""
	if not spec.position.is_finite() or not is_finite(spec.width) or not is_finite(spec.depth):
		problem = "needs a finite position, width and depth"
	elif spec.width < level.ball_radius * 2.0 + 2.0:
		problem = (
			"is %s px wide; a ball needs at least %s"
			% [_num(spec.width), _num(level.ball_radius * 2.0 + 2.0)]
		)
	elif spec.depth < spec.width * 0.5:
		problem = "is shallower than half its width; its cup cannot be built"
	elif not _in(spec.payout, PAYOUT[0], PAYOUT[1]):
		problem = "pays %d balls; a payout is %d to %d" % [spec.payout, PAYOUT[0], PAYOUT[1]]
	elif not _in(spec.symbols, SYMBOLS[0], SYMBOLS[1]):
		problem = "has %d symbols per reel; use %d to %d" % [spec.symbols, SYMBOLS[0], SYMBOLS[1]]
	elif not _in(spec.open_seconds, OPEN_SECONDS[0], OPEN_SECONDS[1]):
		problem = (
			"opens for %s s; use %s to %s"
			% [_num(spec.open_seconds), _num(OPEN_SECONDS[0]), _num(OPEN_SECONDS[1])]
		)
	elif not _in(spec.open_catches, CATCHES[0], CATCHES[1]):
		problem = (
			"closes after %d catches; use %d to %d" % [spec.open_catches, CATCHES[0], CATCHES[1]]
		)
	if problem.is_empty():
		return true
	var where := spec.position if spec.position.is_finite() else at
	BoardIssue.add_to(issues, ERROR, "%s %s." % [name, problem], where, "bad_bonus")
	return false


static func _check_inside_ring(level: BoardLevel, i: int, issues: Array[BoardIssue]) -> void:
	var spec := level.bonus_pockets[i]
	var points := BonusGeometry.rim_pins(level, spec)
	for entry in BonusGeometry.wall_plan(level):
		if entry["item"] == i:
			var tip: Vector2 = entry["b"]
			points.append(tip)
	for petal in BonusGeometry.petal_plan(level):
		if petal["item"] == i:
			points.append(BonusGeometry.petal_tip(petal, 0.0))
			points.append(BonusGeometry.petal_tip(petal, 1.0))
	var reach := level.ring_radius - level.pin_radius - level.ball_radius * 2.0
	for p in points:
		if p.distance_to(level.ring_center) > reach:
			var text := "%s reaches the ring; move it inward so balls can pass round it."
			BoardIssue.add_to(issues, ERROR, text % label(level, i), spec.position, "bonus_outside")
			return


static func _check_field_pins(level: BoardLevel, i: int, issues: Array[BoardIssue]) -> void:
	var box := cup_rect(level, level.bonus_pockets[i]).grow(level.ball_radius)
	for k in level.pins.size():
		if box.has_point(level.pins[k]):
			var text := (
				"Pin %d sits inside %s's cup; a ball could not get in."
				% [ItemIds.of(level, "pins", k), label(level, i)]
			)
			BoardIssue.add_to(issues, ERROR, text, level.pins[k], "bonus_blocked")
			return
	for k in level.pockets.size():
		var pocket := level.pockets[k]
		if pocket == null:
			continue
		var other := Rect2(
			pocket.position - Vector2(pocket.width * 0.5, 0.0), Vector2(pocket.width, pocket.depth)
		)
		if box.intersects(other):
			var text := (
				"%s overlaps pocket %d." % [label(level, i), ItemIds.of(level, "pockets", k)]
			)
			BoardIssue.add_to(issues, ERROR, text, level.bonus_pockets[i].position, "bonus_overlap")
			return


static func _check_overlaps(
	level: BoardLevel, sound: Array[int], issues: Array[BoardIssue]
) -> void:
	for a in sound.size():
		for b in range(a + 1, sound.size()):
			var first := cup_rect(level, level.bonus_pockets[sound[a]]).grow(level.ball_radius)
			if first.intersects(cup_rect(level, level.bonus_pockets[sound[b]])):
				var text := "%s overlaps %s." % [label(level, sound[a]), label(level, sound[b])]
				var at := level.bonus_pockets[sound[b]].position
				BoardIssue.add_to(issues, ERROR, text, at, "bonus_overlap")


static func _check_roles(level: BoardLevel, issues: Array[BoardIssue]) -> void:
	var starts := 0
	var attackers := 0
	for spec in level.bonus_pockets:
		if spec != null:
			starts += 1 if spec.role == BonusPocketSpec.Role.START else 0
			attackers += 1 if spec.role == BonusPocketSpec.Role.ATTACKER else 0
	var at := level.ring_center
	if attackers > 0 and starts == 0:
		var text := "The attacker never opens: add a start pocket to spin the reels."
		BoardIssue.add_to(issues, WARNING, text, at, "bonus_no_start")
	if starts > 0 and attackers == 0:
		var text := "A jackpot opens nothing: add an attacker for the start pocket's reels."
		BoardIssue.add_to(issues, WARNING, text, at, "bonus_no_attacker")


static func _in(value: float, low: float, high: float) -> bool:
	return is_finite(value) and value >= low and value <= high


# "8", "12.5": one decimal at most, none for a whole number.
static func _num(value: float) -> String:
	return str(snappedf(value, 0.1)).trim_suffix(".0")
