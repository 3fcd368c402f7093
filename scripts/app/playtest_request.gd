class_name PlaytestRequest
extends RefCounted
## The play-test request: the board editor writes which board to play, the game reads it
## once when a game scene starts (App.current_board_path). The file is plain JSON read with
## the JSON parser, which only makes plain values: a player could be handed this file, and
## ConfigFile would build any object written in it and run its script.
##
## Every field is checked before the board is used: `board` must be a shipped-levels path
## res://levels/<kind>/<name>.board; `kind` pachinko or maze, matching the folder;
## `written_at` (unix seconds) less than [constant MAX_AGE_SECONDS] old. A request that
## fails any check is removed with a warning saying why.

const PATH := "user://playtest_request.json"
## Where builds before the JSON request wrote it with ConfigFile: removed unread.
const LEGACY_PATH := "user://playtest_request.cfg"
## A request older than this is left over from an editor session that never ran it.
const MAX_AGE_SECONDS := 300.0
## Clocks may disagree a little between writing and reading; a request from further ahead
## than this was not written by this machine's editor.
const FUTURE_SLACK_SECONDS := 5.0
## A real request is under 200 bytes; anything much larger is not one.
const MAX_BYTES := 4096
const FORMAT := 1
const FIELDS := ["format", "board", "kind", "written_at"]
const BOARD_PATTERN := "^res://levels/(pachinko|maze)/[A-Za-z0-9_-]+\\.board$"


## Writes a request to play `board_path` in the game `kind` (BoardLevel.KIND_NAMES).
## Returns "" or a sentence saying what went wrong (nothing is written then).
static func write(board_path: String, kind: String, path := PATH) -> String:
	var now := Time.get_unix_time_from_system()
	var request := {"format": FORMAT, "board": board_path, "kind": kind, "written_at": int(now)}
	var problem := check(request, now)
	if not problem.is_empty():
		return "Play-test: %s." % problem
	var written := SafeWrite.write_text(path, JSON.stringify(request, "\t", false) + "\n")
	if written != OK:
		return "Play-test: could not write %s (%s)." % [path, error_string(written)]
	return ""


## Reads the request at `path` as data: {"board", "kind", "problem"}, where "problem" is ""
## or why the request cannot be used (then board and kind are ""). The bytes are checked
## first (size, NUL, UTF-16, UTF-8; a byte order mark is dropped), so no engine error is printed.
static func read(path := PATH, now := Time.get_unix_time_from_system()) -> Dictionary:
	var bytes := UserFile.read_text(path, MAX_BYTES)
	if bytes.has("missing"):
		return _refused("it does not exist")
	if bytes.has("error"):
		var why: String = bytes["error"]
		return _refused(why)
	var text: String = bytes["text"]
	var json := JSON.new()
	if json.parse(text) != OK:
		var where := json.get_error_line() + 1  # the parser counts lines from 0
		return _refused("it is not JSON (line %d: %s)" % [where, JsonErrors.parse_error(json)])
	if not json.data is Dictionary:
		return _refused("it is not a JSON object")
	var repeated := JsonKeys.repeated(text)
	if not repeated.is_empty():
		return _refused(JsonKeys.problem(repeated))
	var request: Dictionary = json.data
	var problem := check(request, now)
	if not problem.is_empty():
		return _refused(problem)
	return {"board": request["board"], "kind": request["kind"], "problem": ""}


## "" when `request` (parsed JSON) is a usable request at time `now`, else the problem.
static func check(request: Dictionary, now: float) -> String:
	for key: Variant in request:
		if not FIELDS.has(key):
			return "unknown field '%s'" % str(key).left(40)
	for key: String in FIELDS:
		if not request.has(key):
			return "the field '%s' is missing" % key
	var format: Variant = request["format"]
	if not _is_number(format) or _float_of(format) != FORMAT:
		return "format must be %d, got %s" % [FORMAT, _shown(request["format"])]
	var kind: Variant = request["kind"]
	if BoardLevel.kind_named(kind) < 0:
		return "kind must be %s, got %s" % [BoardLevel.kind_choices(), _shown(kind)]
	var board: Variant = request["board"]
	if not board is String or not _board_path_ok(str(board), str(kind)):
		var wanted := "res://levels/%s/<name>.board" % kind
		return (
			"the board must be a file %s (name: letters, digits, _ or -), got %s"
			% [wanted, _shown(board)]
		)
	return _check_age(request["written_at"], now)


## The game side: the board to play for `kind`, or "". A usable request for the other game
## is left for it; a used, stale or bad one is removed (bad ones with a warning).
static func take(kind: String, path := PATH) -> String:
	remove_legacy()
	if not FileAccess.file_exists(path):
		return ""
	var request := read(path)
	var problem: String = request["problem"]
	if not problem.is_empty():
		push_warning(
			"Play-test request %s removed: %s." % [ProjectSettings.globalize_path(path), problem]
		)
		DirAccess.remove_absolute(path)
		return ""
	if request["kind"] != kind:
		return ""
	DirAccess.remove_absolute(path)
	return request["board"]


## Removes a request in the old ConfigFile format without reading it.
static func remove_legacy(legacy_path := LEGACY_PATH) -> void:
	if not FileAccess.file_exists(legacy_path):
		return
	DirAccess.remove_absolute(legacy_path)
	push_warning(
		(
			"Play-test request %s removed unread: it is in the old format; press Play-test again."
			% ProjectSettings.globalize_path(legacy_path)
		)
	)


static func _board_path_ok(board: String, kind: String) -> bool:
	var pattern := RegEx.create_from_string(BOARD_PATTERN)
	var found := pattern.search(board)
	return found != null and found.get_string(1) == kind and not board.contains("..")


static func _check_age(written_at: Variant, now: float) -> String:
	if not _is_number(written_at):
		return "written_at must be a number of unix seconds, got %s" % _shown(written_at)
	var age := now - _float_of(written_at)
	if age < -FUTURE_SLACK_SECONDS:
		return "it was written %d s in the future" % roundi(-age)
	if age >= MAX_AGE_SECONDS:
		return "it is %d s old (stale after %d s)" % [roundi(age), MAX_AGE_SECONDS]
	return ""


static func _is_number(value: Variant) -> bool:
	return (value is float or value is int) and is_finite(_float_of(value))


# `value`, an int or a float, as a float.
static func _float_of(value: Variant) -> float:
	var number: float = value
	return number


# A value as the warning shows it: a number as it is, anything else only by its kind (a
# refusal names the problem, never the file's text).
static func _shown(value: Variant) -> String:
	return str(value).left(24) if _is_number(value) else JsonErrors.kind_of(value)


static func _refused(problem: String) -> Dictionary:
	return {"board": "", "kind": "", "problem": problem}
