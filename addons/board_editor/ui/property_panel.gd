@tool
extends VBoxContainer
## The dock's "Selection" panel: exact numbers for the selected items (ItemProperties),
## each change one undo step. With several items selected, the fields they all have: a
## field where they differ is empty and says "mixed", and a value typed there lands on
## every one of them (their mirror twins too in mirror mode) in one undo step. Also their
## count, align and space buttons, and for pins on an arc the arc's shape (ArcFields).

const NumberRow := preload("res://addons/board_editor/ui/number_row.gd")
const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const ItemProperties := preload("res://addons/board_editor/core/item_properties.gd")
const ItemNames := preload("res://addons/board_editor/core/item_names.gd")
const Arrange := preload("res://addons/board_editor/core/arrange.gd")
const ArrangeAction := preload("res://addons/board_editor/actions/arrange_action.gd")
const ArcFields := preload("res://addons/board_editor/ui/arc_fields.gd")
const BonusActions := preload("res://addons/board_editor/bonus/bonus_actions.gd")
const EditCommands := preload("res://addons/board_editor/core/edit_commands.gd")

## Align buttons: [label, Arrange mode, tooltip].
const ALIGN_BUTTONS := [
	["Left", "left", "Line the selected items up on the leftmost one."],
	["Centre", "center_x", "Line them up on a vertical line through their middle."],
	["Right", "right", "Line them up on the rightmost one."],
	["Top", "top", "Line them up on the topmost one."],
	["Middle", "center_y", "Line them up on a horizontal line through their middle."],
	["Bottom", "bottom", "Line them up on the lowest one."],
]

var _session: BoardEditSession
var _title: Label
var _rows: Dictionary[String, HBoxContainer] = {}
var _fields: Dictionary[String, SpinBox] = {}
var _mixed: Dictionary[String, bool] = {}
var _arrange: HFlowContainer
var _flip: HFlowContainer
var _arc_fields: ArcFields
var _role_row: HBoxContainer
var _role: OptionButton


func _init() -> void:
	var heading := Label.new()
	heading.text = "Selection"
	heading.add_theme_color_override("font_color", Color(0.6, 0.8, 1.0))
	add_child(heading)
	_title = Label.new()
	_title.autowrap_mode = TextServer.AUTOWRAP_WORD_SMART
	add_child(_title)
	_add_role_row()
	for key: String in ItemProperties.FIELDS:
		var spec: Array = ItemProperties.FIELDS[key]
		var row := NumberRow.make(spec)
		var spin := NumberRow.spin_of(row)
		spin.value_changed.connect(_on_value_changed.bind(key))
		# After the SpinBox's own handler: Enter in a mixed field sets every item even when
		# the typed number is the one the box held (no value_changed then).
		spin.get_line_edit().text_submitted.connect(_on_text_submitted.bind(key))
		add_child(row)
		_rows[key] = row
		_fields[key] = spin
	# The arc's shape first: with a long selection the align buttons are the less often used.
	_arc_fields = ArcFields.new()
	add_child(_arc_fields)
	_flip = HFlowContainer.new()
	add_child(_flip)
	_add_button(
		_flip,
		"Flip (H)",
		"Flip the selection left to right about its centre (mirror mode flips the twins too).",
		func() -> void: EditCommands.flip_selection(_session)
	)
	_add_button(
		_flip,
		"Mirror to other half (Shift+M)",
		"Add the selection's mirror image on the other half of the board, keeping it.",
		func() -> void: EditCommands.mirror_to_other_half(_session)
	)
	_arrange = HFlowContainer.new()
	add_child(_arrange)
	for entry: Array in ALIGN_BUTTONS:
		var tip: String = entry[2]
		_arrange_button(history_name(str(entry[1])), tip, align.bind(str(entry[1])))
	_arrange_button(
		history_name("x"), "Space them evenly from left to right.", distribute.bind("x")
	)
	_arrange_button(
		history_name("y"), "Space them evenly from top to bottom.", distribute.bind("y")
	)


# A bonus pocket's role (start pocket, attacker, tulip), shown for one selected bonus pocket.
func _add_role_row() -> void:
	_role_row = HBoxContainer.new()
	var label := Label.new()
	label.text = "Role"
	label.size_flags_horizontal = Control.SIZE_EXPAND_FILL
	_role_row.add_child(label)
	_role = OptionButton.new()
	_role.tooltip_text = "What the pocket does when it catches a ball."
	for role_name: String in BonusPocketSpec.ROLE_NAMES:
		_role.add_item(role_name)
	_role.item_selected.connect(set_role)
	_role_row.add_child(_role)
	add_child(_role_row)


## Gives the one selected bonus pocket another role (one undo step); it stays selected.
func set_role(role: int) -> void:
	if _session == null or _session.selection.size() != 1:
		return
	var item: Vector2i = _session.selection[0]
	if item.x != BoardItems.Kind.BONUS or not BoardItems.is_valid(_session.level, item):
		return
	if _session.level.bonus_pockets[item.y].role == role:
		return
	var action := BonusActions.SetBonusRole.new(_session.level, item.y, role)
	_session.commit(action)
	if action.moved_to >= 0:
		_session.select([Vector2i(BoardItems.Kind.BONUS, action.moved_to)] as Array[Vector2i])
	refresh()


## The role picker (tests and the screenshot hook choose in it).
func role_picker() -> OptionButton:
	return _role


## Lines the selection up (Arrange.ALIGN_MODES); one undo step.
func align(mode: String) -> void:
	var offsets := Arrange.align_offsets(_session.level, _session.selection, mode)
	if not offsets.is_empty():
		_session.commit(ArrangeAction.new(_session.level, offsets, history_name(mode)))


## Spaces the selection evenly along "x" or "y"; one undo step.
func distribute(axis: String) -> void:
	var offsets := Arrange.distribute_offsets(_session.level, _session.selection, axis)
	if not offsets.is_empty():
		_session.commit(ArrangeAction.new(_session.level, offsets, history_name(axis)))


## The words an align or space step goes by, on its button and in the History: "Align
## middle" for "center_y", "Space across" for "x".
static func history_name(mode: String) -> String:
	if mode == "x":
		return "Space across"
	if mode == "y":
		return "Space down"
	for entry: Array in ALIGN_BUTTONS:
		if entry[1] == mode:
			return "Align %s" % str(entry[0]).to_lower()
	return "Arrange"


func _arrange_button(text: String, tooltip: String, action: Callable) -> void:
	_add_button(_arrange, text, tooltip, action)


func _add_button(row: Container, text: String, tooltip: String, action: Callable) -> void:
	var button := Button.new()
	button.text = text
	button.tooltip_text = tooltip
	button.focus_mode = Control.FOCUS_NONE
	button.pressed.connect(func() -> void: action.call())
	row.add_child(button)


## Shows `session`'s selection and edits it from now on.
func bind(session: BoardEditSession) -> void:
	_session = session
	_arc_fields.bind(session)
	refresh()


## The field for `key` (tests and the screenshot hook type into it); arc fields are
## "arc_" + a PinArc key ("arc_radius").
func field(key: String) -> SpinBox:
	if key.begins_with("arc_"):
		return _arc_fields.field(key.trim_prefix("arc_"))
	return _fields[key]


## The heading over the fields ("Tulip 2 at (485, 330)").
func title() -> String:
	return _title.text


## True when field `key` shows "mixed" (the selected items differ in it).
func is_mixed(key: String) -> bool:
	return _mixed.get(key, false)


## Sets field `key` to `value` on the selection, as typing it into the field does.
func set_field(key: String, value: float) -> void:
	if _session == null or _session.selection.is_empty():
		return
	var items := _session.selection
	var axis := _session.mirror_axis() if _session.mirror_enabled else NAN
	var action: BoardAction = null
	if items.size() == 1 and (is_nan(axis) or key in ["x", "y"]):
		if not is_nan(axis):
			action = ItemProperties.mirrored_action_for(_session.level, items[0], key, value, axis)
		if action == null:
			action = ItemProperties.action_for(_session.level, items[0], key, value)
	else:
		action = ItemProperties.action_for_all(_session.level, items, key, value, axis)
	if action != null:
		_session.commit(action)
	refresh()


## Updates the title and the fields from the selection.
func refresh() -> void:
	var values := {}
	if _session == null or _session.level == null:
		_title.text = ""
	elif _session.selection.size() == 1:
		var item: Vector2i = _session.selection[0]
		values = ItemProperties.values_of(_session.level, item)
		_title.text = ItemNames.title(_session.level, item)
	elif _session.selection.is_empty():
		_title.text = "Nothing selected: click an item with the Select tool (Q)."
	else:
		values = ItemProperties.shared_values(_session.level, _session.selection)
		_title.text = (
			"%d items selected: a value typed below sets it on all of them."
			% _session.selection.size()
		)
	var arc := _session.selected_arc() if _session != null else {}
	if not arc.is_empty():
		_title.text = (
			"An arc of %d pins: shape it below, or align or space them." % _session.selection.size()
		)
	_arc_fields.show_arc(arc)
	_show_role()
	_arrange.visible = _session != null and _session.selection.size() >= 2
	_flip.visible = _session != null and not _session.selection.is_empty()
	for key: String in _rows:
		_rows[key].visible = values.has(key)
		var value: float = values.get(key, 0.0)
		_mixed[key] = values.has(key) and is_nan(value)
		if values.has(key):
			_show_value(_fields[key], value)


# A field's value, or an empty box saying "mixed" (NAN: the items differ).
func _show_value(spin: SpinBox, value: float) -> void:
	var text := spin.get_line_edit()
	text.placeholder_text = "mixed"
	if is_nan(value):
		text.text = ""
		return
	spin.set_value_no_signal(value)
	text.text = String.num(spin.value, 0 if spin.step >= 1.0 else 2)


func _on_value_changed(value: float, key: String) -> void:
	set_field(key, value)


func _on_text_submitted(text: String, key: String) -> void:
	if is_mixed(key) and text.strip_edges().is_valid_float():
		var spin := _fields[key]
		var typed := snappedf(text.to_float(), spin.step)
		set_field(key, clampf(typed, spin.min_value, spin.max_value))


func _show_role() -> void:
	var bonus := -1
	if _session != null and _session.level != null and _session.selection.size() == 1:
		var item: Vector2i = _session.selection[0]
		if item.x == BoardItems.Kind.BONUS and BoardItems.is_valid(_session.level, item):
			bonus = item.y
	_role_row.visible = bonus >= 0
	if bonus >= 0:
		_role.select(_session.level.bonus_pockets[bonus].role)
