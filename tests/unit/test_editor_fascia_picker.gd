extends GutTest
## The board dock's "Machine" row: a pachinko board's fascia picked from the five machines in
## one undo step, the board redrawn at once, the row hidden on a maze.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const FasciaPicker := preload("res://addons/board_editor/ui/fascia_picker.gd")
const BoardDock := preload("res://addons/board_editor/ui/board_dock.gd")

var session: BoardEditSession
var picker: FasciaPicker


func _open(path: String) -> BoardLevel:
	var level := BoardLoader.load_board(path).level.duplicate_level()
	session = BoardEditSession.new(level)
	picker = add_child_autofree(FasciaPicker.new())
	picker.bind(session)
	return level


func test_picking_a_machine_is_one_undo_step() -> void:
	var level := _open("res://levels/pachinko/classic.board")
	assert_true(picker.visible)
	assert_eq(picker.picker().selected, FasciaNames.NAMES.find("classic"))
	watch_signals(level)
	var sakura := FasciaNames.NAMES.find("sakura")
	picker.picker().select(sakura)
	picker.picker().item_selected.emit(sakura)
	assert_eq(level.fascia, "sakura")
	assert_signal_emitted(level, "changed", "the board node redraws on this signal")
	assert_eq(Array(session.history.names()), ["Machine: Sakura"], "one step")
	session.history.undo()
	assert_eq(level.fascia, "classic")
	picker.refresh()
	assert_eq(picker.picker().selected, FasciaNames.NAMES.find("classic"), "shows the undo")
	session.history.redo()
	assert_eq(level.fascia, "sakura")


func test_picking_the_machine_it_already_wears_records_nothing() -> void:
	var level := _open("res://levels/pachinko/classic.board")
	picker.pick("classic")
	picker.pick("disco")
	assert_eq(level.fascia, "classic")
	assert_eq(session.history.names().size(), 0)


func test_every_machine_is_offered_by_its_title() -> void:
	_open("res://levels/pachinko/classic.board")
	assert_eq(picker.picker().item_count, FasciaNames.NAMES.size())
	for i in FasciaNames.NAMES.size():
		assert_eq(picker.picker().get_item_text(i), FasciaNames.TITLES[i])


func test_a_maze_has_no_machine_row() -> void:
	_open("res://levels/maze/classic.board")
	assert_false(picker.visible)


func test_the_dock_shows_the_row_for_a_pachinko_board() -> void:
	var dock: BoardDock = add_child_autofree(BoardDock.new())
	var level := BoardLoader.load_board("res://levels/pachinko/fever.board").level
	dock.show_board(BoardEditSession.new(level), [])
	assert_true(dock.machine().visible)
	assert_eq(dock.machine().picker().selected, FasciaNames.NAMES.find("neon"))
