extends RefCounted
## Headless autoplay from the command line:
## `godot --headless --path . -- --autoplay=pachinko --board=classic --seconds=60 --seed=1`.
## Prints one JSON line with what happened and returns the process exit code.

const GAMES := {
	"pachinko": "res://scripts/pachinko/autoplay/pachinko_autoplay.gd",
	"maze": "res://scripts/maze/autoplay/maze_autoplay.gd",
}
const DEFAULT_SECONDS := {"pachinko": 60.0, "maze": 120.0}
const MAX_SECONDS := 3600.0


## True when the user arguments ask for an autoplay run.
static func wants_autoplay(args: PackedStringArray) -> bool:
	for arg in args:
		if arg.begins_with("--autoplay"):
			return true
	return false


## Parses `--key=value` arguments. Unknown keys and malformed values become an error entry.
static func parse(args: PackedStringArray) -> Dictionary:
	var options := {"game": "", "board": "classic", "seconds": -1.0, "seed": 1, "hard": false}
	for arg in args:
		var key := arg.get_slice("=", 0)
		var value := arg.substr(key.length() + 1) if arg.contains("=") else ""
		match key:
			"--autoplay":
				options["game"] = value
			"--board":
				options["board"] = value
			"--seconds":
				if not value.is_valid_float() or float(value) <= 0.0 or float(value) > MAX_SECONDS:
					return {
						"error":
						"--seconds must be a number in (0, %d], got '%s'" % [MAX_SECONDS, value]
					}
				options["seconds"] = float(value)
			"--seed":
				if not value.is_valid_int():
					return {"error": "--seed must be a whole number, got '%s'" % value}
				options["seed"] = int(value)
			"--hard":
				options["hard"] = true
			_:
				return {
					"error":
					(
						"unknown argument '%s' (known: --autoplay= --board= --seconds= --seed= --hard)"
						% arg
					)
				}
	if not GAMES.has(options["game"]):
		return {"error": "--autoplay must be one of %s, got '%s'" % [GAMES.keys(), options["game"]]}
	if float(options["seconds"]) < 0.0:
		options["seconds"] = DEFAULT_SECONDS[options["game"]]
	return options


## Runs the autoplay the arguments ask for; prints one JSON line; returns the exit code.
static func run(args: PackedStringArray) -> int:
	var options := parse(args)
	if options.has("error"):
		printerr("autoplay: %s" % options["error"])
		print(JSON.stringify({"ok": false, "error": options["error"]}))
		return 2
	var game: String = options["game"]
	var board_path := resolve_board_path(game, options["board"])
	var loaded := BoardLoader.load_board(board_path)
	if loaded.level == null:
		printerr("autoplay: %s" % loaded.error)
		print(JSON.stringify({"ok": false, "error": loaded.error}))
		return 2
	var script: Script = load(GAMES[game])
	var result: Dictionary
	if game == "maze":
		result = script.call(
			"run", loaded.level, options["seconds"], options["seed"], options["hard"]
		)
	else:
		result = script.call("run", loaded.level, options["seconds"], options["seed"])
	var report := {
		"ok": true, "game": game, "board": loaded.level.board_id, "seed": options["seed"]
	}
	report.merge(result)
	print(JSON.stringify(report))
	return 0


## A bare board name means levels/<game>/<name>.tres; a res:// path is used as it is.
static func resolve_board_path(game: String, board: String) -> String:
	if board.begins_with("res://") or board.begins_with("user://"):
		return board
	return "res://levels/%s/%s.tres" % [game, board]
