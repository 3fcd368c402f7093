extends GutTest
## The dock's pin-pattern settings show only the fields the chosen pattern reads: an arc is
## placed through three points and takes the pin count alone (its radius field did nothing
## after three-point arcs came in), rows belong to the lattice.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const ToolOptions := preload("res://addons/board_editor/ui/tool_options.gd")
const PatternAction := preload("res://addons/board_editor/actions/pattern_action.gd")

var session: BoardEditSession
var options: ToolOptions


func before_each() -> void:
	var level := BoardLoader.load_board("res://levels/pachinko/classic.board").level
	session = BoardEditSession.new(level.duplicate_level())
	options = add_child_autofree(ToolOptions.new())
	options.bind(session)


func _pick(kind: String) -> void:
	var kinds := options.find_children("*", "OptionButton", true, false)
	var picker := kinds[0] as OptionButton
	var index := PatternAction.KINDS.find(kind)
	picker.select(index)
	picker.item_selected.emit(index)


func test_an_arc_shows_the_pin_count_only() -> void:
	_pick("arc")
	assert_eq(str(session.pattern["kind"]), "arc")
	assert_true(options.shows_pattern_field("count"))
	assert_false(options.shows_pattern_field("spacing"), "three points set the arc's size")
	assert_false(options.shows_pattern_field("rows"))


func test_rows_show_for_a_lattice_and_not_for_a_row() -> void:
	_pick("lattice")
	assert_true(options.shows_pattern_field("rows"))
	assert_true(options.shows_pattern_field("spacing"))
	_pick("row")
	assert_false(options.shows_pattern_field("rows"))
	assert_true(options.shows_pattern_field("spacing"))


func test_no_field_is_named_for_the_arc_radius_any_more() -> void:
	for label: Label in options.find_children("*", "Label", true, false):
		assert_false(label.text.to_lower().contains("radius"), "no dead arc radius: " + label.text)
