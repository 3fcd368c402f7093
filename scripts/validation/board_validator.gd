class_name BoardValidator
extends RefCounted
## Checks a board for everything that would break the game or trap a ball, fast enough to
## run on every edit in the editor. Errors make the loader refuse the board; warnings are
## design hints. Each issue carries a short code (BoardIssue.kind, e.g. "unknown_fascia")
## set by its check.

## Common problems that make the kind-specific checks meaningless.
const BLOCKING := ["bad_kind", "bad_size", "bad_ball_radius"]


## Every problem found on `level`, errors first then warnings, each in board order.
static func validate(level: BoardLevel) -> Array[BoardIssue]:
	var issues: Array[BoardIssue] = []
	if level == null:
		issues.append(
			BoardIssue.new(
				BoardIssue.Severity.ERROR, "There is no board.", Vector2.ZERO, "no_level"
			)
		)
		return issues
	_check_common(level, issues)
	for issue in issues:
		if issue.kind in BLOCKING:
			return issues  # every later check needs a sane kind, size and ball
	if level.kind == BoardLevel.Kind.PACHINKO:
		_check_fascia(level, issues)
		PachinkoChecks.check(level, issues)
	else:
		MazeChecks.check(level, issues)
	var sorted: Array[BoardIssue] = []
	for issue in issues:
		if issue.is_error():
			sorted.append(issue)
	for issue in issues:
		if not issue.is_error():
			sorted.append(issue)
	return sorted


## Only the errors of `validate`.
static func errors(level: BoardLevel) -> Array[BoardIssue]:
	var found: Array[BoardIssue] = []
	for issue in validate(level):
		if issue.is_error():
			found.append(issue)
	return found


static func _check_common(level: BoardLevel, issues: Array[BoardIssue]) -> void:
	if level.version < 0 or level.version > BoardLevel.CURRENT_VERSION:
		_error(
			issues,
			(
				"Unknown file version %d (this build reads up to %d)."
				% [level.version, BoardLevel.CURRENT_VERSION]
			),
			Vector2.ZERO,
			"unknown_version"
		)
	if level.kind != BoardLevel.Kind.PACHINKO and level.kind != BoardLevel.Kind.MAZE:
		_error(issues, "Unknown board kind %d." % level.kind, Vector2.ZERO, "bad_kind")
	if level.board_id.strip_edges().is_empty():
		_error(
			issues,
			"The board has no id (board_id is used for best scores).",
			Vector2.ZERO,
			"missing_id"
		)
	if level.display_name.strip_edges().is_empty():
		_warning(issues, "The board has no display name.", Vector2.ZERO, "missing_name")
	if not level.size.is_finite() or level.size.x <= 0.0 or level.size.y <= 0.0:
		_error(
			issues,
			"The board size must be positive, got %s." % level.size,
			Vector2.ZERO,
			"bad_size"
		)
	if not is_finite(level.ball_radius) or level.ball_radius <= 0.0:
		_error(
			issues,
			"The ball radius must be positive, got %s." % level.ball_radius,
			Vector2.ZERO,
			"bad_ball_radius"
		)
	_check_tuning(level.tuning, issues)


# The machine the board is dressed as must be one the game can draw (the file reader's own
# list, so a board that passes here loads again).
static func _check_fascia(level: BoardLevel, issues: Array[BoardIssue]) -> void:
	if FasciaNames.is_known(level.fascia):
		return
	_error(
		issues,
		(
			'The board is dressed as "%s", a machine this game does not have: pick %s.'
			% [level.fascia, FasciaNames.choices()]
		),
		Vector2.ZERO,
		"unknown_fascia"
	)


static func _check_tuning(tuning: PhysicsTuning, issues: Array[BoardIssue]) -> void:
	if tuning == null:
		_warning(
			issues,
			"The board has no physics tuning; the game uses the defaults.",
			Vector2.ZERO,
			"no_tuning"
		)
		return
	# The file reader's own ranges (BoardRanges), so a board that passes here loads again.
	var fields := BoardRanges.tuning_fields()
	var names: Array = fields.keys()
	names.sort()
	for name: String in names:
		var low: float = fields[name][1]
		var high: float = fields[name][2]
		var value: Variant = tuning.get(name)
		var parts: Array = [value.x, value.y] if value is Vector2 else [value]
		for part: float in parts:
			if not is_finite(part) or part < low or part > high:
				var text := (
					"Tuning %s must be %s to %s, got %s."
					% [name, String.num(low), String.num(high), value]
				)
				_error(issues, text, Vector2.ZERO, "bad_tuning")
				break


static func _error(issues: Array[BoardIssue], text: String, at: Vector2, code: String) -> void:
	issues.append(BoardIssue.new(BoardIssue.Severity.ERROR, text, at, code))


static func _warning(issues: Array[BoardIssue], text: String, at: Vector2, code: String) -> void:
	issues.append(BoardIssue.new(BoardIssue.Severity.WARNING, text, at, code))
