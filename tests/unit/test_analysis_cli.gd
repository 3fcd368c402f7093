extends GutTest
## The --analyze command once its flags are parsed: the JSON line's keys, the files it
## writes, and bad input.

const KEYS := [
	"board",
	"shots",
	"seed",
	"threads",
	"wall_s",
	"shots_per_s",
	"return",
	"return_ci95",
	"pockets",
	"bands",
	"dead_pockets",
	"heatmap"
]

var _saved_dir := ""


func before_each() -> void:
	_saved_dir = AnalyzeCli.out_dir_override
	AnalyzeCli.out_dir_override = "build/test_analysis"


func after_each() -> void:
	AnalyzeCli.out_dir_override = _saved_dir


func test_a_pachinko_run_writes_its_report_and_heat_map() -> void:
	var values := {"analyze": "pachinko", "board": "classic", "shots": 300, "seed": 4, "threads": 2}
	assert_eq(AnalyzeCli.run(values), 0)
	var json := ProjectSettings.globalize_path("res://build/test_analysis/pachinko_classic.json")
	var report: Dictionary = JSON.parse_string(FileAccess.get_file_as_string(json))
	for key: String in KEYS:
		assert_true(report.has(key), "the report has %s" % key)
	assert_eq(report["shots"], 300.0)
	assert_eq((report["bands"] as Array).size(), 5)
	var pocket: Dictionary = report["pockets"][0]
	for key: String in ["id", "payout", "hits", "rate", "ci95"]:
		assert_true(pocket.has(key), "a pocket has %s" % key)
	var png := ProjectSettings.globalize_path("res://" + str(report["heatmap"]))
	var image := Image.load_from_file(png)
	assert_not_null(image, "the heat map is a PNG")
	if image != null:
		assert_eq(image.get_size(), Vector2i(700, 700), "drawn at the board's size")


func test_played_fires_the_shots_as_the_autoplay_and_says_so() -> void:
	var values := {"analyze": "pachinko", "board": "classic", "shots": 60, "seed": 4, "threads": 1}
	assert_eq(AnalyzeCli.run(values), 0)
	var json := ProjectSettings.globalize_path("res://build/test_analysis/pachinko_classic.json")
	var report: Dictionary = JSON.parse_string(FileAccess.get_file_as_string(json))
	assert_false(report["played"], "by default the balls fly alone (the editor's fast run)")
	values["played"] = true
	assert_eq(AnalyzeCli.run(values), 0)
	report = JSON.parse_string(FileAccess.get_file_as_string(json))
	assert_true(report["played"], "--played fires them as the autoplay does")


func test_profile_times_the_stages_and_changes_no_figure() -> void:
	var values := {"analyze": "pachinko", "board": "classic", "shots": 250, "seed": 3, "threads": 1}
	var json := ProjectSettings.globalize_path("res://build/test_analysis/pachinko_classic.json")
	assert_eq(AnalyzeCli.run(values), 0)
	var plain: Dictionary = JSON.parse_string(FileAccess.get_file_as_string(json))
	assert_false(plain.has("profile"), "no profile unless asked for")
	values["profile"] = true
	assert_eq(AnalyzeCli.run(values), 0)
	var timed: Dictionary = JSON.parse_string(FileAccess.get_file_as_string(json))
	var profile: Dictionary = timed.get("profile", {})
	for stage: String in AnalysisProfile.NAMES:
		assert_true(profile.get("seconds", {}).has(stage), "the profile times %s" % stage)
	assert_eq(profile.get("chunks"), 1.0, "one chunk of 250 shots")
	assert_gt(float(profile.get("climb_ball_steps", 0)), 0.0, "the rail climbs are counted")
	for key: String in ["profile", "wall_s", "shots_per_s", "report"]:
		plain.erase(key)
		timed.erase(key)
	assert_eq(timed, plain, "the same figures with and without the profile")


func test_bad_input_exits_2() -> void:
	var missing := {"analyze": "pachinko", "board": "no_such_board", "shots": 10, "seed": 1}
	assert_eq(AnalyzeCli.run(missing), 2)
	var no_shots := {"analyze": "pachinko", "board": "classic", "shots": 0, "seed": 1}
	assert_eq(AnalyzeCli.run(no_shots), 2)
	var wrong_game := {"analyze": "maze", "board": "res://levels/pachinko/classic.board", "seed": 1}
	assert_eq(AnalyzeCli.run(wrong_game), 2)


func test_out_puts_the_report_in_that_folder_and_names_it_whole() -> void:
	var folder := ProjectSettings.globalize_path("user://test_analysis_out/deeper")
	var values := {
		"analyze": "pachinko",
		"board": "classic",
		"shots": 20,
		"seed": 1,
		"threads": 1,
		"out": folder
	}
	assert_eq(AnalyzeCli.run(values), 0)
	var json := folder.path_join("pachinko_classic.json")
	assert_true(FileAccess.file_exists(json), "the report is in the --out folder, made for it")
	var report: Dictionary = JSON.parse_string(FileAccess.get_file_as_string(json))
	assert_eq(report["report"], json, "the report names where it is")
	assert_eq(report["heatmap"], folder.path_join("pachinko_classic.png"))
	for name in ["pachinko_classic.json", "pachinko_classic.png"]:
		DirAccess.remove_absolute(folder.path_join(name))
	DirAccess.remove_absolute(folder)
	DirAccess.remove_absolute(folder.get_base_dir())


# Issue 39: the exported game wrote build/analysis/ under whatever folder the player stood
# in. This runs on both builds: the release test run checks the player's side.
func test_without_out_the_game_writes_beside_the_players_files() -> void:
	AnalyzeCli.out_dir_override = ""
	var values := {"analyze": "pachinko", "board": "classic", "shots": 20, "seed": 1, "threads": 1}
	assert_eq(AnalyzeCli.run(values), 0)
	var folder := (
		ProjectSettings.globalize_path("user://reports")
		if OS.has_feature("template")
		else ProjectSettings.globalize_path("res://build/analysis")
	)
	var json := folder.path_join("pachinko_classic.json")
	assert_true(FileAccess.file_exists(json), "written to %s" % folder)
	if OS.has_feature("template"):
		for name in ["pachinko_classic.json", "pachinko_classic.png"]:
			DirAccess.remove_absolute(folder.path_join(name))


func test_workers_give_the_report_of_threads_here() -> void:
	if not AnalysisWorker.available():
		pass_test("no worker process on this platform")
		return
	if OS.has_feature("release_tests"):
		# a worker started from the test pack's binary would open the pack's GUT runner
		pass_test("workers are started from the game's own binary, not the test pack's")
		return
	var json := ProjectSettings.globalize_path("res://build/test_analysis/pachinko_fever.json")
	var reports: Array[Dictionary] = []
	for workers: int in [0, 2]:
		var values := {
			"analyze": "pachinko", "board": "fever", "shots": 500, "seed": 2, "workers": workers
		}
		values["threads"] = 1
		assert_eq(AnalyzeCli.run(values), 0, "workers: %d" % workers)
		var report: Dictionary = JSON.parse_string(FileAccess.get_file_as_string(json))
		for key: String in ["wall_s", "shots_per_s"]:
			report.erase(key)
		reports.append(report)
	assert_true(reports[0].has("bonus"), "Fever's bonus-open figures are in")
	assert_eq(JSON.stringify(reports[1]), JSON.stringify(reports[0]), "the same report")


# This process's share can finish a short pooled run before a worker's engine has started:
# that worker then finds its queue gone and leaves at once, without a word (it printed "the
# file does not exist" for the queue's board, and would have failed on a board name).
func test_a_worker_whose_queue_is_gone_leaves_quietly() -> void:
	var gone := ProjectSettings.globalize_path("user://no_such_folder/1_2.queue")
	var values := {"analyze": "pachinko", "board": "no_such_board", "shots": 10, "seed": 1}
	values["queue"] = gone
	values["worker_id"] = 0
	assert_eq(AnalyzeCli.run(values), 0, "nothing left to do is no failure")


# The first pooled run in a fresh user folder finds no worker folder yet: no engine error
# (GUT fails a test on one) while looking for stale queues.
func test_no_stale_queue_in_a_folder_not_made_yet() -> void:
	AnalysisQueueFolder.remove_stale(ProjectSettings.globalize_path("user://no_such_folder"))
	pass_test("no error for a missing folder")


func test_bad_worker_counts_are_refused() -> void:
	var values := {"analyze": "pachinko", "board": "classic", "shots": 10, "seed": 1}
	values["workers"] = -1
	assert_eq(AnalyzeCli.run(values), AnalyzeCli.EXIT_BAD_INPUT, "negative")
	values["workers"] = 65
	assert_eq(AnalyzeCli.run(values), AnalyzeCli.EXIT_BAD_INPUT, "too many")
	values["workers"] = 2
	values["profile"] = true
	assert_eq(AnalyzeCli.run(values), AnalyzeCli.EXIT_BAD_INPUT, "--profile times this process")
