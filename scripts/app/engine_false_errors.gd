class_name EngineFalseErrors
## The one false error of Debian's release build of Godot 4.6.3, told apart from real ones.
##
## Each time a control leaves a container, that build reports "Attempt to disconnect a
## nonexistent connection" for the container's own size_flags_changed and visibility_changed
## connections: the connection exists, but the optimised build cannot match it (its debug
## build and editor do; a ten-line project shows it, tests/README.md). The engine made the
## callable in C++, so it has no name: a callable our scripts make always has one, so a real
## mistake of ours never matches. The launcher (tools/release/files/board-studio) keeps the
## same reports off the console, GameLogFile off the log file, and the release test run's
## KnownEngineErrors off GUT's error list.

## The engine function and file that make the report.
const FUNCTION := "_disconnect"
const FILE := "core/object/object.cpp"
## The failed condition, which is what the release build's report carries.
const CONDITION := "slot_map.has"
## The signals Container connects on each child.
const SIGNALS: PackedStringArray = ["size_flags_changed", "visibility_changed"]
## What the message says of an unnamed (engine-made) callable.
const UNNAMED_CALLABLE := "callable: ''"


## Whether an engine error report (as a Logger receives it) is the false disconnect report.
static func is_false_disconnect(
	function: String, file: String, code: String, rationale: String
) -> bool:
	if function != FUNCTION or not file.ends_with(FILE):
		return false
	if not code.contains(CONDITION) and not rationale.contains("nonexistent connection"):
		return false
	# the release build's report carries the condition and, in the message, the signal
	var text := code + " " + rationale
	if rationale.is_empty():
		# no message: only the condition, and nothing names the callable
		return true
	if not text.contains(UNNAMED_CALLABLE):
		return false
	for signal_name in SIGNALS:
		if text.contains("Signal: '%s'" % signal_name):
			return true
	return false
