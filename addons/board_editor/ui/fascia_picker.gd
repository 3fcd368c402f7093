@tool
extends HBoxContainer
## The dock's "Machine" row for a pachinko board: which machine the board is dressed as (its
## `fascia`: art, palette and name plate, FasciaNames). Picking one is one undo step, and the
## board view shows it at once (BoardPainter draws the machine's art and colours).

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const SetPropertiesAction := preload("res://addons/board_editor/actions/set_properties_action.gd")

var _session: BoardEditSession
var _picker: OptionButton


func _init() -> void:
	var label := Label.new()
	label.text = "Machine"
	label.size_flags_horizontal = Control.SIZE_EXPAND_FILL
	add_child(label)
	_picker = OptionButton.new()
	_picker.tooltip_text = (
		"The machine this board is dressed as: the art behind the pins, the colours\n"
		+ "and the name plate. Looks only: how the board plays stays the same."
	)
	for title in FasciaNames.TITLES:
		_picker.add_item(title)
	# Cut a long name short rather than widen the dock.
	_picker.fit_to_longest_item = false
	_picker.clip_text = true
	_picker.size_flags_horizontal = Control.SIZE_EXPAND_FILL
	_picker.item_selected.connect(func(index: int) -> void: pick(FasciaNames.NAMES[index]))
	add_child(_picker)


## Edits `session`'s board from now on (null: none); shown for pachinko boards only.
func bind(session: BoardEditSession) -> void:
	_session = session
	refresh()


## Dresses the board as machine `fascia_name` (FasciaNames.NAMES): one undo step.
func pick(fascia_name: String) -> void:
	if _session == null or _session.level == null or not FasciaNames.is_known(fascia_name):
		return
	if _session.level.fascia == fascia_name:
		return
	var title := FasciaNames.title_of(fascia_name).get_slice(":", 0)
	_session.commit(
		SetPropertiesAction.new(_session.level, {"fascia": fascia_name}, "Machine: " + title)
	)
	refresh()


## Shows the board's machine (after an undo, say).
func refresh() -> void:
	var level := _session.level if _session != null else null
	visible = level != null and level.is_pachinko()
	if visible:
		_picker.select(FasciaNames.NAMES.find(level.fascia))


## The drop-down (tests and the screenshot hook choose in it).
func picker() -> OptionButton:
	return _picker
