class_name LevelSlot
extends VBoxContainer
## One place in the level select's grid: a board's card and, under it, what can be done with
## its file: export (any board) and delete (the player's own boards only). Those two buttons
## are for the mouse: they never take focus, so the arrows and the d-pad go card to card
## (keys and pads reach them through the card's menu, card_actions_menu.gd, which a right
## click on the card opens too).

## The player asked to export this board's file.
signal export_requested(board_path: String)
## The player asked to delete this board (only offered for the player's own boards).
signal delete_requested(board_path: String, shown_name: String)
## The player right-clicked the card: its menu should open (the card has the focus).
signal menu_requested(card: LevelCard)

## The board's card (a Button; pressing it plays a playable board).
var card: LevelCard = null

var _export_button: Button = null
var _delete_button: Button = null
var _shown := ""


## Builds the slot for the file at `path`, showing "Loading…" until `fill` is called.
## `mine`: a board of the player's own, which may be deleted.
func _init(path: String, mine: bool) -> void:
	name = path.get_file().get_basename().validate_node_name()
	add_theme_constant_override("separation", 6)
	card = LevelCard.new()
	card.mine = mine
	card.show_loading(path)
	card.gui_input.connect(_on_card_gui_input)
	add_child(card)
	var actions := HBoxContainer.new()
	actions.alignment = BoxContainer.ALIGNMENT_CENTER
	actions.add_theme_constant_override("separation", 10)
	add_child(actions)
	_export_button = _small_button(actions, "Export…", "Save a copy of this board's file to share")
	_export_button.pressed.connect(func() -> void: export_requested.emit(card.board_path))
	if mine:
		_delete_button = _small_button(actions, "Delete…", "Remove this board from My boards")
		_delete_button.pressed.connect(
			func() -> void: delete_requested.emit(card.board_path, _shown_name())
		)


## Fills the card from a finished load (`best`: the best-result line, "" for none).
func fill(result: BoardLoadResult, best: String) -> void:
	card.setup(result, best)
	_shown = result.level.display_name if result.ok() else ""


## A locked maze board (maze progression) offers no export: the player has not reached it
## (trial 10 found Export… under the locked cards). Hidden, not greyed: the theme draws a
## greyed small button at the full button's size.
func show_locked(is_locked: bool) -> void:
	_export_button.visible = not is_locked


## True for a board of the player's own (it can be deleted).
func is_mine() -> bool:
	return _delete_button != null


## What the player knows this board by: its name, or its file's when it did not load.
func shown_name() -> String:
	return _shown_name()


## The export button (for tests and the mouse).
func export_button() -> Button:
	return _export_button


## The delete button, or null on a shipped board.
func delete_button() -> Button:
	return _delete_button


func _on_card_gui_input(event: InputEvent) -> void:
	var click := event as InputEventMouseButton
	if click != null and click.pressed and click.button_index == MOUSE_BUTTON_RIGHT:
		card.grab_focus()
		card.accept_event()
		menu_requested.emit(card)


func _shown_name() -> String:
	return _shown if not _shown.is_empty() else card.board_path.get_file()


static func _small_button(row: HBoxContainer, words: String, tip: String) -> Button:
	var button := Button.new()
	button.text = words
	button.tooltip_text = tip
	button.theme_type_variation = &"SmallButton"
	button.focus_mode = Control.FOCUS_NONE
	row.add_child(button)
	return button
