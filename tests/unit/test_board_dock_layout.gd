extends GutTest
## The Board dock has a column of its own: one scrolling body and no scroll inside it (the
## problems and the balance table grow with their lines), a width that nothing in it can
## push wider (a balance table used to widen it from 220 px to the table's 330), the
## problems, Selection, tool settings and analysis in view at 1920x1080, and a scroll
## position that stays where the designer left it when the board is shown again.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardDock := preload("res://addons/board_editor/ui/board_dock.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const Plugin := preload("res://addons/board_editor/plugin.gd")
const TEST_FOLDER := "user://test_board_dock_layout"
## The height the dock's column gets in the editor at 1920x1080 (the window less the menu
## bar, the dock's tab and the bottom panel's bar), px.
const FULL_HD_HEIGHT := 930.0

var _saved_folder := ""


func before_each() -> void:
	_saved_folder = AnalysisCache.folder_override
	AnalysisCache.folder_override = TEST_FOLDER


func after_each() -> void:
	if DirAccess.dir_exists_absolute(TEST_FOLDER):
		for file in DirAccess.get_files_at(TEST_FOLDER):
			DirAccess.remove_absolute(TEST_FOLDER.path_join(file))
	AnalysisCache.folder_override = _saved_folder


func _dock() -> BoardDock:
	var dock: BoardDock = add_child_autofree(BoardDock.new())
	dock.size = Vector2(BoardDock.DOCK_WIDTH, FULL_HD_HEIGHT)
	return dock


func _classic() -> BoardLevel:
	return BoardLoader.load_board("res://levels/pachinko/classic.board").level


# Every problem the validator could give, many times over: a long list.
func _many_issues() -> Array[BoardIssue]:
	var issues: Array[BoardIssue] = []
	for i in 40:
		var text := "Pins %d and %d overlap: move one of them a little to the side." % [i, i + 1]
		issues.append(BoardIssue.new(BoardIssue.Severity.WARNING, text, Vector2(10, 10)))
	return issues


func test_one_scrolling_body_and_no_scroll_inside_it() -> void:
	var dock := _dock()
	var session := BoardEditSession.new(_classic())
	dock.show_board(session, _many_issues())
	var scrolls: Array[Node] = []
	for scroll in dock.find_children("*", "ScrollContainer", true, false):
		if not _in_popup(scroll, dock):  # a drop-down's own list scrolls in its own window
			scrolls.append(scroll)
	assert_eq(scrolls, [dock.body()] as Array[Node], "the body is the only scroll container")
	var table := dock.analysis.balance_table()
	assert_false(table.scroll_vertical_enabled, "the balance table shows every line")
	assert_true(dock.body().is_ancestor_of(dock.problems()), "the problems scroll with it")
	assert_true(dock.body().is_ancestor_of(dock.properties()), "and the Selection panel")


func _in_popup(node: Node, dock: Node) -> bool:
	var up := node.get_parent()
	while up != null and up != dock:
		if up is Window:
			return true
		up = up.get_parent()
	return false


func test_nothing_in_the_dock_pushes_it_wider() -> void:
	var dock := _dock()
	var empty_width := dock.get_combined_minimum_size().x
	var level := _classic()
	var session := BoardEditSession.new(level)
	dock.show_board(session, _many_issues())
	var panel := dock.analysis
	panel.shots = 260
	panel.bind(level)
	panel.start()
	while panel.is_running():
		panel._process(0.016)
		OS.delay_msec(10)
	assert_true(panel.balance_table().visible, "the balance table is shown")
	session.select([BoardItems.make(BoardItems.Kind.POCKET, 0)] as Array[Vector2i])
	dock.refresh_options()
	await wait_process_frames(2)
	assert_eq(dock.get_combined_minimum_size().x, empty_width, "the same width as empty")
	assert_eq(empty_width, BoardDock.DOCK_WIDTH)


func test_problems_selection_tools_and_analysis_are_in_view_at_1920x1080() -> void:
	var dock := _dock()
	var level := _classic()
	var session := BoardEditSession.new(level)
	session.select([BoardItems.make(BoardItems.Kind.POCKET, 0)] as Array[Vector2i])
	var issues: Array[BoardIssue] = [
		BoardIssue.new(BoardIssue.Severity.WARNING, "Pins 3 and 4 overlap.", Vector2(10, 10))
	]
	dock.show_board(session, issues)
	dock.refresh_options()
	await wait_process_frames(3)
	var bottom := dock.get_global_rect().end.y
	var controls: Dictionary[String, Control] = {
		"the problems": dock.problems(),
		"the Selection fields": dock.properties().field("payout"),
		"the tool settings": dock.find_children("*", "OptionButton", true, false)[-1],
		"Analyze": dock.analysis.find_children("*", "Button", true, false)[0],
	}
	for what: String in controls:
		var box := controls[what].get_global_rect()
		assert_true(box.size.y > 0.0 and box.end.y <= bottom, "%s in view" % what)


func test_the_scroll_position_stays_when_the_board_is_shown_again() -> void:
	var dock := _dock()
	dock.size = Vector2(BoardDock.DOCK_WIDTH, 400)
	var session := BoardEditSession.new(_classic())
	dock.show_board(session, _many_issues())
	await wait_process_frames(3)
	dock.body().scroll_vertical = 300
	# An edit validates again: the same problems, the rows built anew.
	dock.show_board(session, _many_issues())
	await wait_process_frames(3)
	assert_eq(dock.body().scroll_vertical, 300)
	dock.refresh_options()
	await wait_process_frames(3)
	assert_eq(dock.body().scroll_vertical, 300, "after a selection change too")


func test_a_wide_screen_gives_the_dock_a_column_of_its_own() -> void:
	assert_eq(Plugin.dock_slot_for(1920), EditorPlugin.DOCK_SLOT_RIGHT_UR, "beside the Inspector")
	assert_eq(Plugin.dock_slot_for(1366), EditorPlugin.DOCK_SLOT_RIGHT_BL, "under it at 1366")
