class_name BoardCheckCli
extends RefCounted
## `--check-boards`: loads every file in the board folders (levels/<kind>/ and the player's
## user://boards/<kind>/) through BoardLoader and prints one JSON line per file,
## `{"path", "ok", "error", "warnings", "load_ms"}`, then a summary line. Exit 0 when every
## board loads, 1 when any is refused. Nothing a file holds can crash or hang it: the reader
## and the schema bound every file before a board is built.

const PLAYER_ROOT := "user://boards"
const KINDS: Array[int] = [BoardLevel.Kind.PACHINKO, BoardLevel.Kind.MAZE]


## Runs the check (the flag table's `runs` entry); returns the exit code.
static func run(_values: Dictionary) -> int:
	var checked := 0
	var refused := 0
	var started := Time.get_ticks_msec()
	for root: String in [BoardLoader.LEVELS_DIR, PLAYER_ROOT]:
		for kind in KINDS:
			for line in check_folder(root, kind):
				print(JSON.stringify(line))
				checked += 1
				refused += 0 if line["ok"] else 1
	var summary := {
		"summary": true,
		"boards": checked,
		"ok": checked - refused,
		"refused": refused,
		"total_ms": Time.get_ticks_msec() - started,
	}
	print(JSON.stringify(summary))
	return 1 if refused > 0 else 0


## One report line per file in `<root>/<kind name>/`, in file-name order.
static func check_folder(root: String, kind: int) -> Array[Dictionary]:
	var lines: Array[Dictionary] = []
	for path in BoardLoader.list_files(kind, root):
		var started := Time.get_ticks_usec()
		var loaded := BoardLoader.load_listed(path, kind, root)
		var elapsed_ms := (Time.get_ticks_usec() - started) / 1000.0
		(
			lines
			. append(
				{
					"path": loaded.path,
					"ok": loaded.ok(),
					"error": loaded.error,
					"warnings": loaded.warnings.size(),
					"load_ms": snappedf(elapsed_ms, 0.01),
				}
			)
		)
	return lines
