class_name LevelSelectFocus
extends RefCounted
## Where the keys' and the pad's focus goes on the level select, and the grids' columns it
## follows: as many columns as the list is wide, the cards sharing the row's width (both
## sections alike, so their cards line up), the arrows' neighbours (CardGridFocus), the
## first playable card once the boards have loaded (the board last played, when it is
## listed and playable: a play trial came back from a board to find Classic focused), and
## after a delete the next card at
## the same scroll, so the player stays where they were.

## Room between cards, across and down (the grids' separations in the scene).
const CARD_GAP := 22
## At most this many cards in a row, however wide the window.
const MAX_COLUMNS := 4

## Room (px) kept for the list's scroll bar beside the cards.
const BAR_ROOM := 16.0

## Cards in a row, in both sections.
var columns := 3
## How wide every card is drawn: the row's width shared by its cards (LevelCard.CARD_SIZE.x
## at least).
var card_width := LevelCard.CARD_SIZE.x

## The board the focus goes to once listed (the one last played), "" for the first card.
var preferred_path := ""

var _sections: Array[CardSection] = []
var _scroll: ScrollContainer = null
var _import: Button = null  # takes the focus when there is no card at all
var _back: Button = null  # takes the focus back when no card is playable
var _first_focus: Control = null
# after a delete: the board whose card takes the focus (the next one), and where the list
# was scrolled to
var _refocus_path := ""
var _kept_scroll := -1


## Focus over the cards of `sections` (shipped first, then My boards) in `scroll`.
func _init(
	sections: Array[CardSection], scroll: ScrollContainer, import_button: Button, back: Button
) -> void:
	_sections = sections
	_scroll = scroll
	_import = import_button
	_back = back


## The cards shown (every section, in order).
func cards() -> Array[Button]:
	var result: Array[Button] = []
	for section in _sections:
		result.append_array(section.cards())
	return result


## The first playable card, else the first card, else null.
func first_card() -> Button:
	var all := cards()
	for card in all:
		if not card.disabled:
			return card
	return all[0] if not all.is_empty() else null


## Sets the columns to what a list `list_width` wide holds and the cards' width to fill the
## row, then the arrows' neighbours again. The width is the one the window gives the list,
## not its size now: cards as wide as an old, wider row would hold the list that wide.
func fit_columns(list_width: float) -> void:
	var room := list_width - maxf(BAR_ROOM, _bar_width())
	var fits := floori((room + CARD_GAP) / (LevelCard.CARD_SIZE.x + CARD_GAP))
	var wanted := clampi(fits, 1, MAX_COLUMNS)
	var width := maxf(LevelCard.CARD_SIZE.x, floorf((room - CARD_GAP * (wanted - 1)) / wanted))
	if wanted == columns and width == card_width:
		return
	columns = wanted
	card_width = width
	for section in _sections:
		section.grid.columns = wanted
	link()


## Links every card to its neighbours for the arrows and the d-pad (and gives new cards
## the row's width).
func link() -> void:
	_size_slots()
	var lists: Array = []
	for section in _sections:
		var list: Array[Control] = []
		for card in section.cards():
			list.append(card)
		lists.append(list)
	CardGridFocus.link(lists, columns)


## A section was listed again: a deleted board's neighbour takes the focus back, or, on
## the first listing, the first card (the Import button when there is none).
func after_listing() -> void:
	if _refocus_path != "":
		_take_place_back()
	elif not is_instance_valid(_first_focus):
		var first := _starting_card()
		_first_focus = first if first != null else _import
		_focus_quietly(_first_focus)
	elif _scroll.get_viewport().gui_get_focus_owner() == _first_focus:
		_move_to_preferred()  # the player has not moved: the board last played, now listed


## Everything has loaded: the first playable card takes the focus the loading card held.
func after_loading() -> void:
	var viewport := _scroll.get_viewport()
	var focused := viewport.gui_get_focus_owner()
	var stuck := focused == _first_focus and focused is Button and (focused as Button).disabled
	if focused == null or stuck:
		take_back()
	elif focused == _first_focus:
		_move_to_preferred()  # the player has not moved: the board last played, now listed
	if viewport.gui_get_focus_owner() == _shipped_first_card():
		# the first row from its top, not scrolled to wherever the loading card sat
		_scroll.set_deferred("scroll_vertical", 0)
	_first_focus = viewport.gui_get_focus_owner()


## The maze's cards were put in the order they open: the card the focus started on (the
## player has not moved) is kept in view where it now sits. It had been scrolled to where its
## file's name first listed it (trial 5 saw the list open scrolled down while loading).
func after_reorder() -> void:
	var focused := _scroll.get_viewport().gui_get_focus_owner()
	if focused == null or focused != _first_focus:
		return
	if focused == _shipped_first_card():
		_scroll.set_deferred("scroll_vertical", 0)
	else:
		_scroll.ensure_control_visible.call_deferred(focused)


## Gives the focus to the board last played, else the first playable card (the Back button
## when there is no card).
func take_back() -> void:
	var first := _starting_card()
	(first if first != null else _back).grab_focus()


## The card the focus starts on: the board last played when it is listed and playable, else
## the first playable card.
func preferred_card() -> Button:
	for card in cards():
		if (card as LevelCard).board_path == preferred_path and not card.disabled:
			return card
	return null


# Focuses `control` without the list following it there at once: the maze's cards are
# still being put in order, and the list scrolled to where the file's name first put it
# (trial 5 saw it open scrolled down while loading). after_reorder brings it into view.
func _focus_quietly(control: Control) -> void:
	var follow := _scroll.follow_focus
	_scroll.follow_focus = false
	control.grab_focus()
	_scroll.follow_focus = follow
	if control != _shipped_first_card():
		_scroll.ensure_control_visible.call_deferred(control)


func _starting_card() -> Button:
	var preferred := preferred_card()
	return preferred if preferred != null else first_card()


func _move_to_preferred() -> void:
	var preferred := preferred_card()
	if preferred != null and preferred != _first_focus:
		preferred.grab_focus()
		_first_focus = preferred
		_scroll.ensure_control_visible.call_deferred(preferred)


## Before a delete: remembers the card after the deleted one (or before it, for the last)
## and the scroll, for after_listing.
func keep_place_after_delete(board_path: String) -> void:
	var mine: Array[Button] = []
	for section in _sections:
		if section.mine:
			mine.append_array(section.cards())
	_refocus_path = ""
	for i in mine.size():
		if (mine[i] as LevelCard).board_path == board_path:
			var neighbour := i + 1 if i + 1 < mine.size() else i - 1
			if neighbour >= 0:
				_refocus_path = (mine[neighbour] as LevelCard).board_path
	if _refocus_path == "":
		_refocus_path = board_path  # none left: the Import button takes the focus
	_kept_scroll = _scroll.scroll_vertical


func _take_place_back() -> void:
	var slot: LevelSlot = null
	for section in _sections:
		if slot == null:
			slot = section.slot_of(_refocus_path)
	(slot.card if slot != null else _import as Control).grab_focus()
	_scroll.set_deferred("scroll_vertical", _kept_scroll)
	_refocus_path = ""


func _size_slots() -> void:
	for section in _sections:
		for slot in section.slots():
			slot.custom_minimum_size.x = card_width


func _bar_width() -> float:
	return _scroll.get_v_scroll_bar().get_combined_minimum_size().x


func _shipped_first_card() -> Button:
	for child in _sections[0].grid.get_children():
		if child is LevelSlot:
			return (child as LevelSlot).card
	return null
