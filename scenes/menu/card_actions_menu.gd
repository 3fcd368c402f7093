class_name CardActionsMenu
extends PopupMenu
## The small menu of one level select card: Play, Export a copy…, and Delete… for the
## player's own boards. Opened from the focused card (the board_actions key or button, or a
## right click), so the arrows and the d-pad never wander onto a card's file actions. It only
## asks: the level select plays, and its dialogs export or delete (each with its own dialog).

## The player chose an entry for the board at `board_path`.
signal chosen(choice: Choice, board_path: String)

## What can be done with a board.
enum Choice { PLAY, EXPORT, DELETE }

const THEME := preload("res://scenes/menu/ui_theme.tres")

var _board_path := ""


func _ready() -> void:
	theme = THEME
	hide_on_checkable_item_selection = false
	id_pressed.connect(func(id: int) -> void: chosen.emit(id as Choice, _board_path))


## Opens the menu for the board at `board_path` just inside `card_rect` (screen
## coordinates). `playable`: Play is offered enabled; `mine`: Delete… is offered; `locked`:
## a maze board not open yet, whose file is not offered for export (trial 10).
func open_for(
	board_path: String, card_rect: Rect2, playable: bool, mine: bool, locked := false
) -> void:
	_board_path = board_path
	clear()
	add_item("Play", Choice.PLAY)
	set_item_disabled(item_count - 1, not playable)
	if not locked:
		add_item("Export a copy…", Choice.EXPORT)
	if mine:
		add_item("Delete…", Choice.DELETE)
	var corner := card_rect.position + Vector2(card_rect.size.x * 0.12, card_rect.size.y * 0.1)
	popup(Rect2i(Vector2i(corner), Vector2i(int(card_rect.size.x * 0.76), 0)))
	set_focused_item(0 if playable or item_count < 2 else 1)


## The entries' texts, top to bottom (for tests).
func entries() -> PackedStringArray:
	var found := PackedStringArray()
	for index in item_count:
		found.append(get_item_text(index))
	return found
