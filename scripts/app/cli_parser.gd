class_name CliParser
extends RefCounted
## Parses the user arguments against the flag table (cli_flags.gd). Every argument must be a
## known flag with a good value; anything else is an error that names the argument, so a typo
## never silently starts the game.

## An unknown flag at least this similar to a known one gets a "did you mean" hint.
const HINT_SIMILARITY := 0.6


## What the arguments ask for.
class Parsed:
	extends RefCounted
	## The command flag, such as "--autoplay"; "" plays the game.
	var command := ""
	## Each given flag's value by key (cli_flags.gd key_of), with the command's defaults.
	var values := {}
	## "" or a sentence naming the argument that could not be used.
	var error := ""

	static func failed(problem: String) -> Parsed:
		var parsed := Parsed.new()
		parsed.error = problem
		return parsed


## Parses `args` (OS.get_cmdline_user_args()). `--help` wins over every other flag once
## all of them parse, so `--autoplay=maze --help` shows help.
static func parse(args: PackedStringArray) -> Parsed:
	var given := {}  # flag → its value as typed, "" for a switch
	for arg in args:
		var problem := _take_argument(arg, given)
		if not problem.is_empty():
			return Parsed.failed(problem)
	var parsed := Parsed.new()
	if given.has("--help"):
		parsed.command = "--help"
		return parsed
	var commands := _commands_in(given)
	if commands.size() > 1:
		return Parsed.failed("%s cannot be used together: pick one" % " and ".join(commands))
	parsed.command = commands[0] if commands.size() == 1 else ""
	for flag: String in given:
		var row := CliFlags.find(flag)
		var problem := _check_belongs(row, parsed.command)
		if problem.is_empty():
			var text: String = given[flag]
			problem = _read_value(row, text, parsed.values)
		if not problem.is_empty():
			return Parsed.failed(problem)
	_fill_defaults(parsed)
	return parsed


# Records one argument in `given`; returns "" or what is wrong with it.
static func _take_argument(arg: String, given: Dictionary) -> String:
	if not arg.begins_with("--") or arg.length() < 3:
		return "'%s' is not a flag: flags look like --name or --name=value" % arg
	var flag := arg.get_slice("=", 0)
	var row := CliFlags.find(flag)
	if row.is_empty():
		return "unknown flag '%s'%s" % [flag, _hint_for(flag)]
	if given.has(flag):
		return "%s is given twice" % flag
	var has_value := arg.contains("=")
	if row["value"] == CliFlags.Value.NONE and has_value:
		return "%s takes no value, got '%s'" % [flag, arg]
	if row["value"] != CliFlags.Value.NONE and not has_value:
		return "%s needs a value: %s" % [flag, CliFlags.usage_of(row)]
	given[flag] = arg.substr(flag.length() + 1) if has_value else ""
	return ""


# " (did you mean --seed?)" for a near miss, else "".
static func _hint_for(flag: String) -> String:
	var best := ""
	var best_score := HINT_SIMILARITY
	for row: Dictionary in CliFlags.FLAGS:
		var score := flag.similarity(str(row["flag"]))
		if score >= best_score:
			best = row["flag"]
			best_score = score
	return " (did you mean %s?)" % best if not best.is_empty() else ""


static func _commands_in(given: Dictionary) -> PackedStringArray:
	var commands := PackedStringArray()
	for flag: String in given:
		if CliFlags.find(flag).get("command", false):
			commands.append(flag)
	return commands


# "" when the option works with `command` (a command always belongs).
static func _check_belongs(row: Dictionary, command: String) -> String:
	if row.get("command", false):
		return ""
	var works_with: Array = row.get("for", [])
	if works_with.has(command):
		return ""
	var needed := " or ".join(PackedStringArray(works_with))
	if command.is_empty():
		return "%s needs a command to go with: %s" % [row["flag"], needed]
	return "%s does not work with %s, only with %s" % [row["flag"], command, needed]


# Converts `text` as the row's value kind into `values`; returns "" or the problem.
static func _read_value(row: Dictionary, text: String, values: Dictionary) -> String:
	var flag: String = row["flag"]
	var key := CliFlags.key_of(flag)
	match row["value"]:
		CliFlags.Value.NONE:
			values[key] = true
		CliFlags.Value.CHOICE:
			var choices: Array = row["choices"]
			if not choices.has(text):
				var listed := ", ".join(PackedStringArray(choices))
				return "%s must be one of %s, got '%s'" % [flag, listed, text]
			values[key] = text
		CliFlags.Value.WHOLE:
			if not text.is_valid_int():
				return "%s must be a whole number, got '%s'" % [flag, text]
			values[key] = text.to_int()
		CliFlags.Value.SECONDS:
			var most: float = row["max"]
			if not text.is_valid_float() or text.to_float() <= 0.0 or text.to_float() > most:
				return "%s must be a number in (0, %d], got '%s'" % [flag, most, text]
			values[key] = text.to_float()
		CliFlags.Value.TEXT:
			if text.strip_edges().is_empty():
				return "%s needs a value: %s" % [flag, CliFlags.usage_of(row)]
			values[key] = text
	return ""


# The command's options that were not given take their table default.
static func _fill_defaults(parsed: Parsed) -> void:
	for row: Dictionary in CliFlags.FLAGS:
		var works_with: Array = row.get("for", [])
		var key := CliFlags.key_of(str(row["flag"]))
		if works_with.has(parsed.command) and row.has("default") and not parsed.values.has(key):
			parsed.values[key] = row["default"]
