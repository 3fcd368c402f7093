extends Logger
## Takes the one false error of Debian's release template back out of GUT's error list, so
## the release test run fails on every other engine error, and counts them
## (assert_engine_error_count) as the editor run does. That build reports
## "Condition !s->slot_map.has(...)" from Object::_disconnect each time a control leaves a
## container (size_flags_changed, visibility_changed): the connection exists, the release
## build cannot match it (see the launcher, tools/release/files/board-studio, which keeps
## the same lines off the player's console). Added after GUT's own error tracker, so the
## error it has just recorded is the one taken out.

## How many reports were taken out.
var taken_out := 0


func _log_error(
	function: String,
	file: String,
	_line: int,
	code: String,
	rationale: String,
	_editor_notify: bool,
	_error_type: int,
	_script_backtraces: Array[ScriptBacktrace]
) -> void:
	if not EngineFalseErrors.is_false_disconnect(function, file, code, rationale):
		return
	# the tracker hands out its own list for the running test: the report is taken from it
	var tracked_errors: Array = GutUtils.get_error_tracker().get_current_test_errors()
	for at in range(tracked_errors.size() - 1, -1, -1):
		var tracked: GutTrackedError = tracked_errors[at]
		if tracked.function == EngineFalseErrors.FUNCTION and tracked.code == code:
			tracked_errors.remove_at(at)
			taken_out += 1
			return
