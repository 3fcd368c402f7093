class_name SessionsCli
extends RefCounted
## The `--sessions=N` command: the pachinko session report of PachinkoSessions for a board,
## printed as one JSON line. command_line.gd hands it the parsed flags (cli_flags.gd).

## A board that cannot be loaded (cli_flags.gd EXIT_USAGE).
const EXIT_BAD_BOARD := 2


## The `--sessions=N` command (keys sessions, board, seed): prints one JSON line; 0 when the
## sessions were played, EXIT_BAD_BOARD when the board is not a pachinko board or N < 1.
static func run(values: Dictionary) -> int:
	var count: int = values["sessions"]
	var path := AutoplayCli.resolve_board_path("pachinko", str(values["board"]))
	var loaded := BoardLoader.load_board(path)
	var problem := ""
	if loaded.level == null:
		problem = loaded.error
	elif not loaded.level.is_pachinko():
		problem = "%s is not a pachinko board" % path
	elif count < 1:
		problem = "--sessions needs at least 1 session, got %d" % count
	if not problem.is_empty():
		printerr("sessions: %s" % problem)
		print(JSON.stringify({"ok": false, "error": problem}))
		return EXIT_BAD_BOARD
	var report := {"ok": true, "board": loaded.level.board_id}
	var seed_value: int = values["seed"]
	report.merge(PachinkoSessions.report_for(loaded.level, count, seed_value))
	print(JSON.stringify(report))
	return 0
