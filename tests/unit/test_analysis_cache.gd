extends GutTest
## Analysis results cached per board content, and the warnings made from them.

const TEST_FOLDER := "user://test_analysis_cache"

var _saved_folder := ""


func before_each() -> void:
	_saved_folder = AnalysisCache.folder_override
	AnalysisCache.folder_override = TEST_FOLDER


func after_each() -> void:
	var files := (
		DirAccess.get_files_at(TEST_FOLDER)
		if DirAccess.dir_exists_absolute(TEST_FOLDER)
		else PackedStringArray()
	)
	for file in files:
		DirAccess.remove_absolute(TEST_FOLDER.path_join(file))
	AnalysisCache.folder_override = _saved_folder


func _classic() -> BoardLevel:
	return BoardLoader.load_board("res://levels/pachinko/classic.board").level


# A report on Classic's pockets (each paying what the board's pocket pays).
func _report(dead: Array, ret: float, aim: float) -> Dictionary:
	var pockets := []
	var level := _classic()
	for p in level.pockets.size():
		pockets.append({"id": p, "rate": 0.0, "hits": 0, "payout": level.pockets[p].payout})
	return {
		"version": AnalysisReport.VERSION,
		"shots": 10000,
		"return": ret,
		"return_ci95": 0.02,
		"aim_tv": aim,
		"pockets": pockets,
		"bands": [{"pocket_rates": [0, 0, 0, 0, 0]}],
		"dead_pockets": dead,
	}


func test_the_key_follows_the_board_content_and_settings() -> void:
	var level := _classic()
	var plan := AnalysisPlan.create(level, 1000, 1)
	var key := AnalysisCache.key_for(plan)
	assert_eq(AnalysisCache.key_for(AnalysisPlan.create(level.duplicate_level(), 1000, 1)), key)
	assert_ne(AnalysisCache.key_for(AnalysisPlan.create(level, 1000, 2)), key, "another seed")
	level.pins[0] += Vector2(3, 0)
	level.notify_edited()
	assert_ne(AnalysisCache.key_for(plan), key, "a moved pin makes the result stale")


func test_an_edit_invalidates_the_cached_result() -> void:
	var level := _classic()
	var key := AnalysisCache.key_for(AnalysisPlan.create(level, AnalysisPlan.EDITOR_SHOTS, 1))
	var heat := Image.create(4, 4, false, Image.FORMAT_RGBA8)
	heat.fill(Color.RED)
	assert_eq(AnalysisCache.save(key, _report([2], 0.6, 0.5), heat), OK)
	var cached := AnalysisCache.cached_report(level)
	assert_eq(cached.get("dead_pockets"), [2.0], "reopening the same board finds it")
	assert_eq(AnalysisCache.load_heatmap(key).get_pixel(1, 1), Color.RED)
	var pocket := level.pockets[0]
	pocket.payout += 1
	var priced := AnalysisCache.cached_report(level)
	assert_eq(priced.get("dead_pockets"), [2.0], "a payout edit keeps the counts...")
	assert_eq(priced["pockets"][0]["payout"], pocket.payout, "...priced with the new payout")
	pocket.width += 2.0
	assert_true(AnalysisCache.cached_report(level).is_empty(), "after an edit: nothing cached")


func test_a_damaged_entry_is_ignored() -> void:
	DirAccess.make_dir_recursive_absolute(TEST_FOLDER)
	var file := FileAccess.open(TEST_FOLDER.path_join("bad.json"), FileAccess.WRITE)
	file.store_string('{"version": 1, "shots": "many"}')
	file.close()
	assert_true(AnalysisCache.load_report("bad").is_empty())
	assert_null(AnalysisCache.load_heatmap("missing"))


func test_warnings_name_dead_pockets_a_sure_win_and_power_that_does_not_aim() -> void:
	var level := _classic()
	var issues := AnalysisWarnings.issues(level, _report([1.0, 3.0], 1.25, 0.1))
	var kinds: Array[String] = []
	for issue in issues:
		kinds.append(issue.kind)
		assert_false(issue.is_error(), "numbers warn, they never refuse a board")
	assert_eq(
		kinds,
		[
			"analysis_dead_pocket",
			"analysis_dead_pocket",
			"analysis_return_high",
			"analysis_power_no_aim",
		]
	)
	assert_eq(issues[0].position, level.pockets[1].position)
	assert_string_contains(issues[0].message, "Pocket 2")
	assert_string_contains(issues[2].message, "1.25")
	assert_true(AnalysisWarnings.issues(level, _report([], 0.8, 0.6)).is_empty(), "a fair board")
	assert_true(AnalysisWarnings.issues(level, {}).is_empty(), "not analysed: no warnings")


func test_a_rename_or_a_new_file_name_keeps_the_cache_key_an_edit_does_not() -> void:
	var level := _classic()
	var key := AnalysisCache.key_for(AnalysisPlan.create(level, 1000, 1))
	level.display_name = "Classic, renamed"
	level.board_id = "pachinko_classic_copy"
	level.description = "Another blurb."
	assert_eq(AnalysisCache.key_for(AnalysisPlan.create(level, 1000, 1)), key, "same play")
	level.pockets[0].payout += 1
	assert_eq(AnalysisCache.key_for(AnalysisPlan.create(level, 1000, 1)), key, "a payout edit")
	level.pockets[0].depth += 1
	assert_ne(AnalysisCache.key_for(AnalysisPlan.create(level, 1000, 1)), key, "a pocket edit")
