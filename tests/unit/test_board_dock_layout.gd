extends GutTest
## The Board dock needs no more height than its header, the problem list and a few panel
## rows: the analysis scrolls with the panels. Before, the analysis sat in the dock itself
## and the minimum heights added up to more than the dock gets in the default layout
## (1920x1080: the analysis with its balance table, the problem list's 150 px, the panels'
## 160 px), so the dock ran off the bottom of the window and the Selection panel showed one
## row, or none.

const Session := preload("res://addons/board_editor/board_edit_session.gd")
const BoardDock := preload("res://addons/board_editor/ui/board_dock.gd")

## The title, counts, machine picker, three buttons, the problem list (150 px) and the
## panels' 160 px fit in this.
const DOCK_MOST := 720.0


func _dock_with_classic() -> BoardDock:
	var dock: BoardDock = add_child_autofree(BoardDock.new())
	var level := BoardLoader.load_board("res://levels/pachinko/classic.board").level
	dock.show_board(Session.new(level), [])
	return dock


func test_a_tall_analysis_scrolls_instead_of_stretching_the_dock() -> void:
	var dock := _dock_with_classic()
	# A long balance table makes the analysis section tall.
	dock.analysis.custom_minimum_size = Vector2(0, 400)
	await wait_process_frames(2)
	assert_lt(dock.get_combined_minimum_size().y, DOCK_MOST)


func test_the_analysis_scrolls_with_the_selection_panel() -> void:
	var dock := _dock_with_classic()
	var panel: Control = dock.properties()
	var scroll: Node = panel.get_parent()
	while scroll != null and not scroll is ScrollContainer:
		scroll = scroll.get_parent()
	assert_not_null(scroll, "the Selection panel is in a scrolling body")
	assert_true(scroll.is_ancestor_of(dock.analysis), "with the analysis")
	assert_eq(dock.problems().get_parent(), dock, "the problems stay in view")
