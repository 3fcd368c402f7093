extends GutTest
## The dock's balance table and payout-only edits: counts are cached by the board without
## its payouts, so a payout change prices them again at once (no new shots) and gives the
## very figures a new run would; the table lists every paying item (bonus pieces too) with
## shares that add up to 1, sorts by a column, keeps the figures before an edit beside the
## new ones, and a click on a line picks the item.

const AnalysisPanel := preload("res://addons/board_editor/analysis/analysis_panel.gd")
const BalanceRows := preload("res://addons/board_editor/analysis/balance_rows.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const TEST_FOLDER := "user://test_balance_table_editdock"
const SHOTS := 260

var _saved_folder := ""


func before_each() -> void:
	_saved_folder = AnalysisCache.folder_override
	AnalysisCache.folder_override = TEST_FOLDER


func after_each() -> void:
	if DirAccess.dir_exists_absolute(TEST_FOLDER):
		for file in DirAccess.get_files_at(TEST_FOLDER):
			DirAccess.remove_absolute(TEST_FOLDER.path_join(file))
	AnalysisCache.folder_override = _saved_folder


func _board(board_name: String) -> BoardLevel:
	return BoardLoader.load_board("res://levels/pachinko/%s.board" % board_name).level


func _panel() -> AnalysisPanel:
	var panel := AnalysisPanel.new()
	panel.shots = SHOTS
	add_child_autofree(panel)
	return panel


func _run(panel: AnalysisPanel) -> void:
	panel.start()
	var started := Time.get_ticks_msec()
	while panel.is_running() and Time.get_ticks_msec() - started < 60000:
		panel._process(0.016)
		OS.delay_msec(10)


func _report_of(level: BoardLevel) -> Dictionary:
	var plan := AnalysisPlan.create(level, SHOTS, 1)
	return AnalysisReport.build(plan, PachinkoAnalysis.new(plan).run(), 1.0)


func _set_payout(level: BoardLevel, pocket: int, payout: int) -> void:
	level.pockets[pocket].payout = payout
	level.notify_edited()


func test_the_cache_key_leaves_payouts_out_but_not_geometry() -> void:
	var level := _board("classic")
	var key := AnalysisCache.key_for(AnalysisPlan.create(level, SHOTS, 1))
	_set_payout(level, 1, 12)
	level.display_name = "Renamed"
	assert_eq(AnalysisCache.key_for(AnalysisPlan.create(level, SHOTS, 1)), key)
	level.pockets[1].width += 2.0
	level.notify_edited()
	assert_ne(AnalysisCache.key_for(AnalysisPlan.create(level, SHOTS, 1)), key)


func test_repricing_gives_the_figures_a_new_run_would() -> void:
	var level := _board("classic")
	var before := _report_of(level)
	_set_payout(level, 0, 15)
	_set_payout(level, 2, 1)
	var fresh := _report_of(level)
	var priced := ReportPayouts.repriced(before, level)
	assert_ne(priced["return"], before["return"], "the payouts changed the return")
	assert_eq(priced["return"], fresh["return"])
	assert_eq(priced["return_ci95"], fresh["return_ci95"])
	assert_eq(priced["expected_return"], fresh["expected_return"])
	for b in fresh["bands"].size():
		assert_eq(priced["bands"][b]["return"], fresh["bands"][b]["return"], "band %d" % b)
	for p in fresh["pockets"].size():
		assert_eq(priced["pockets"][p]["payout"], fresh["pockets"][p]["payout"])


func test_a_payout_change_updates_the_return_at_once_with_no_new_run() -> void:
	var level := _board("classic")
	var panel := _panel()
	panel.bind(level)
	_run(panel)
	var first: Dictionary = panel.report()
	var old_return := AnalysisReport.number(first["return"])
	var hits := AnalysisReport.number(first["pockets"][1]["hits"])
	var old_payout: int = level.pockets[1].payout
	_set_payout(level, 1, old_payout + 10)
	panel.bind(level)
	assert_false(panel.is_running(), "no new run")
	var now: Dictionary = panel.report()
	assert_eq(AnalysisReport.number(now["shots"]), float(SHOTS), "the same shots")
	assert_almost_eq(
		AnalysisReport.number(now["return"]), old_return + hits * 10.0 / SHOTS, 0.00002
	)
	assert_almost_eq(panel.return_before(), old_return, 0.00001, "the return before is kept")
	# A reopened board (another panel) finds the counts on disk and prices them too.
	var reopened := _panel()
	reopened.bind(level.duplicate_level())
	assert_eq(reopened.report()["return"], now["return"])


func test_the_table_shows_before_and_now_side_by_side() -> void:
	var level := _board("classic")
	var panel := _panel()
	panel.bind(level)
	_run(panel)
	var table := panel.balance_table()
	assert_true(table.visible)
	assert_eq(table.cell("Pocket 2", 4), "", "nothing before the first run")
	var share_before := table.cell("Pocket 2", 3)
	var old_payout: int = level.pockets[1].payout
	_set_payout(level, 1, old_payout + 10)
	panel.bind(level)
	assert_eq(table.cell("Pocket 2", 1), str(old_payout + 10), "the new payout")
	assert_eq(table.cell("Pocket 2", 4), "%s (%d)" % [share_before, old_payout])
	assert_ne(table.cell("Pocket 2", 3), share_before, "its share grew")
	# An edit of the geometry: no figures now, and the next run is compared with these.
	level.pins[0] += Vector2(0, 1)
	level.notify_edited()
	panel.bind(level)
	assert_false(table.visible, "nothing analysed since the edit")
	_run(panel)
	assert_ne(table.cell("Pocket 2", 4), "", "the figures before the run stay beside")


func test_every_paying_item_has_a_line_and_the_shares_add_up_to_one() -> void:
	for board_name: String in ["classic", "tulips"]:
		var level := _board(board_name)
		var rows := BalanceRows.rows(_report_of(level), level)
		var paying := level.pockets.size() + level.bonus_pockets.size()
		assert_eq(rows.size(), paying + 1, "%s: each paying item and the rail" % board_name)
		assert_almost_eq(BalanceRows.share_total(rows), 1.0, 1e-9, board_name)
		if board_name == "tulips":
			var names := BalanceRows.by_name(rows)
			assert_true(names.has("Tulip 1"), "bonus pieces are listed: %s" % [names.keys()])
			var tulip: BalanceRows.Row = names["Tulip 1"]
			assert_eq(tulip.item, BoardItems.make(BoardItems.Kind.BONUS, _first_tulip(level)))


func test_sorting_and_picking_an_item() -> void:
	var level := _board("classic")
	_set_payout(level, 2, 40)
	var panel := _panel()
	panel.bind(level)
	_run(panel)
	var table := panel.balance_table()
	table.sort_by(1)
	assert_eq(table.line_names()[0], "Pocket 3", "the highest payout first")
	table.sort_by(1)
	assert_eq(table.line_names()[-1], "Pocket 3", "the same title again turns the order")
	table.sort_by(0)
	assert_eq(table.line_names()[0], "Pocket 1", "names in board order")
	watch_signals(panel)
	table.get_root().get_child(2).select(0)
	assert_signal_emitted_with_parameters(
		panel, "item_picked", [BoardItems.make(BoardItems.Kind.POCKET, 2)]
	)


func _first_tulip(level: BoardLevel) -> int:
	for i in level.bonus_pockets.size():
		if level.bonus_pockets[i].role == BonusPocketSpec.Role.TULIP:
			return i
	return -1


func test_the_return_before_stays_when_another_board_is_shown_and_back() -> void:
	var level := _board("classic")
	var panel := _panel()
	panel.bind(level)
	_run(panel)
	var old_return := AnalysisReport.number(panel.report()["return"])
	_set_payout(level, 1, level.pockets[1].payout + 10)
	panel.bind(level)
	assert_almost_eq(panel.return_before(), old_return, 0.00001)
	# Another scene tab: the board is let go (null), another board shows, then this again.
	panel.bind(null)
	panel.bind(_board("tulips"))
	assert_true(is_nan(panel.return_before()), "the other board has no figures before")
	panel.bind(null)
	panel.bind(level)
	assert_almost_eq(panel.return_before(), old_return, 0.00001, "(before: ...) is kept")
	assert_string_contains(panel._controls.status.text, "(before: %.2f)" % old_return)
