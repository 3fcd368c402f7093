extends GutTest
## One real start of the game binary with an unknown flag (the bug this pins: such a start
## used to run the game headless and never return). It must exit 2 at once, naming the flag.

## A start that has not ended by then hangs: it is killed and the test fails.
const DEADLINE_MS := 60000


func test_unknown_flag_exits_2_naming_it_instead_of_starting_the_game() -> void:
	var project := ProjectSettings.globalize_path("res://")
	var args := PackedStringArray(["--headless", "--path", project, "--", "--optimise=pachinko"])
	var started := OS.execute_with_pipe(OS.get_executable_path(), args)
	assert_false(started.is_empty(), "the game binary started")
	if started.is_empty():
		return
	var pid: int = started["pid"]
	var begun := Time.get_ticks_msec()
	while OS.is_process_running(pid) and Time.get_ticks_msec() - begun < DEADLINE_MS:
		await get_tree().create_timer(0.1).timeout
	var hung := OS.is_process_running(pid)
	if hung:
		OS.kill(pid)
	assert_false(hung, "the start with an unknown flag never ended")
	var errors := (started["stderr"] as FileAccess).get_as_text()
	assert_eq(OS.get_process_exit_code(pid), 2, errors)
	assert_string_contains(errors, "unknown flag '--optimise'")
