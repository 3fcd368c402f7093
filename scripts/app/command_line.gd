class_name CommandLine
extends RefCounted
## What a start with user arguments (after `--`) does: nothing special without any, help,
## or the command the flag table names; bad flags print why on stderr and exit with
## [constant CliFlags.EXIT_USAGE] before anything of the game starts.

## What [method run] returns when the game should start as usual.
const START_GAME := -1


## Handles `args`; returns the process exit code, or [constant START_GAME].
static func run(args: PackedStringArray) -> int:
	if args.is_empty():
		return START_GAME
	var parsed := CliParser.parse(args)
	if not parsed.error.is_empty():
		printerr("board-studio: %s" % parsed.error)
		printerr("Run with -- --help to see every flag with an example.")
		return CliFlags.EXIT_USAGE
	if parsed.command.is_empty():
		return START_GAME
	if parsed.command == "--help":
		print(CliHelp.text())
		return CliFlags.EXIT_OK
	var runner: Script = CliFlags.find(parsed.command)["runs"]
	var exit_code: int = runner.call("run", parsed.values)
	return exit_code
