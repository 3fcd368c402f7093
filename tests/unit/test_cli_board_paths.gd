extends GutTest
## Real starts of the game binary with `--autoplay=KIND --board=...`: paths outside the board
## folders (other res:// folders, `..`, absolute paths, the user folder's other files) exit 2
## naming the problem, hostile fixtures are refused the same way, and a board in the player's
## user://boards/ plays from the command line.

## A start that has not ended by then hangs: it is killed and the test fails.
const DEADLINE_MS := 90000
const PLAYER_BOARD := "user://boards/pachinko/zz_test_cli_board_paths.board"
## --board values that must be refused, each with a part of the message that must name why.
const REFUSED := {
	"res://tests/fixtures/hostile_boards/pachinko/object_in_field.board": "boards load only from",
	"res://levels/../tests/fixtures/hostile_boards/pachinko/nan.board": "'..' parts",
	"res://levels/pachinko/../../project.godot": "'..' parts",
	"../../../../etc/passwd": "'..' parts",
	"user://boards/../settings.cfg": "'..' parts",
	"user://settings.cfg": "boards load only from",
	"/etc/passwd": "not a plain file path",
	"res://levels/pachinko/classic.board.uid": "must be a .board file",
}


func after_all() -> void:
	DirAccess.remove_absolute(PLAYER_BOARD)


## Starts the game with `args` after "--"; returns {code, out, err} once it ended.
func _run(args: Array) -> Dictionary:
	var project := ProjectSettings.globalize_path("res://")
	var full := PackedStringArray(["--headless", "--path", project, "--"])
	full.append_array(PackedStringArray(args))
	var started := OS.execute_with_pipe(OS.get_executable_path(), full)
	if started.is_empty():
		return {"code": -1, "out": "", "err": "the game binary did not start"}
	var pid: int = started["pid"]
	var begun := Time.get_ticks_msec()
	while OS.is_process_running(pid) and Time.get_ticks_msec() - begun < DEADLINE_MS:
		await get_tree().create_timer(0.1).timeout
	if OS.is_process_running(pid):
		OS.kill(pid)
		return {"code": -2, "out": "", "err": "hung"}
	return {
		"code": OS.get_process_exit_code(pid),
		"out": (started["stdio"] as FileAccess).get_as_text(),
		"err": (started["stderr"] as FileAccess).get_as_text(),
	}


func test_boards_outside_the_board_folders_are_refused_with_exit_2() -> void:
	for board: String in REFUSED:
		var ran: Dictionary = await _run(["--autoplay=pachinko", "--board=" + board])
		assert_eq(ran["code"], 2, "%s: %s" % [board, ran["err"]])
		assert_string_contains(str(ran["err"]), REFUSED[board], board)
		assert_string_contains(str(ran["out"]), '"ok":false', board)


func test_a_board_in_my_boards_plays_from_the_command_line() -> void:
	DirAccess.make_dir_recursive_absolute(PLAYER_BOARD.get_base_dir())
	var file := FileAccess.open(PLAYER_BOARD, FileAccess.WRITE)
	file.store_buffer(FileAccess.get_file_as_bytes("res://levels/pachinko/classic.board"))
	file.close()
	var args := ["--autoplay=pachinko", "--board=" + PLAYER_BOARD, "--seconds=2", "--seed=3"]
	var ran: Dictionary = await _run(args)
	assert_eq(ran["code"], 0, str(ran["err"]))
	assert_string_contains(str(ran["out"]), '"ok":true')
	assert_string_contains(str(ran["out"]), '"board":"my:zz_test_cli_board_paths"')
