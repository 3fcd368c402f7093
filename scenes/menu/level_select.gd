class_name LevelSelect
extends Control
## The level select of one game (App.level_select_kind): the shipped boards (levels/<kind>/)
## and the player's own ("My boards", user://boards/<kind>/), one card per file. Files load
## off the main thread (CardSection): cards say "Loading…" and fill in, so a slow or hostile
## file never stops the screen; a board that fails to load is greyed with its error.
## My boards can be imported (button or a file dropped on the window), exported and deleted.
## Shipped maze boards come in the order they open (MazeCardOrder) with medals and locks.
## The arrows and the d-pad move card to card (LevelSelectFocus), Enter / A plays, and a
## card's own menu (board_actions: X / Square, or a right click) offers Play, Export and Delete.

const TITLES := {BoardLevel.PACHINKO_NAME: "Pachinko", BoardLevel.MAZE_NAME: "Tilt Maze"}
## At most this many files of a folder get a card (README "Safety"); the rest are counted.
const MAX_LISTED := 200
## At most this many loaded files fill their card in one frame, so a burst never stalls one.
const FILLS_PER_FRAME := 24
## At most this many cards are made in one frame: the screen shows at once and fills up.
const SLOTS_PER_FRAME := 24

## The game whose boards are listed (a name of BoardLevel.KIND_NAMES).
var kind := BoardLevel.PACHINKO_NAME
## The player's boards folder (tests point it at a scratch folder before adding the screen).
var user_root := BoardLoader.USER_DIR
## Loads one file (path, kind, root) -> BoardLoadResult; empty means BoardLoader.load_listed.
## Tests pass a slow one.
var load_one := Callable()

var _imports := BoardImportQueue.new()  # imports check and copy off the main thread
var _not_listed := 0  # files in My boards past MAX_LISTED
var _shipped: CardSection = null
var _mine: CardSection = null
var _focus: LevelSelectFocus = null

@onready var _title: Label = %TitleLabel
@onready var _summary: Label = %SummaryLabel
@onready var _status: Label = %StatusLabel
@onready var _my_empty: Label = %MyBoardsEmpty
@onready var _folder: PathLabel = %FolderLabel
@onready var _back: Button = %BackButton
@onready var _import: Button = %ImportButton
@onready var _dialogs: MyBoardsDialogs = %Dialogs
@onready var _scroll: ScrollContainer = %Scroll
@onready var _card_menu: CardActionsMenu = %CardMenu
@onready var _hint: Label = %Hint


func _ready() -> void:
	kind = App.level_select_kind
	_shipped = _section(%Cards as GridContainer, false)
	_mine = _section(%MyCards as GridContainer, true)
	_focus = LevelSelectFocus.new([_shipped, _mine] as Array[CardSection], _scroll, _import, _back)
	_focus.preferred_path = App.last_board_path(kind)
	_back.pressed.connect(App.go_to_menu)
	_import.pressed.connect(_dialogs.ask_import)
	_dialogs.import_chosen.connect(_import_one)
	_dialogs.export_chosen.connect(export_board)
	_dialogs.delete_confirmed.connect(delete_board)
	_card_menu.chosen.connect(_on_card_menu_chosen)
	_scroll.resized.connect(_fit_columns)
	get_viewport().size_changed.connect(_fit_columns)
	get_window().files_dropped.connect(import_files)
	_imports.titles = TITLES
	_title.text = "%s: choose a board" % TITLES.get(kind, kind.capitalize())
	_say("", false)
	_hint.text = LevelSelectWords.keys_hint()
	reload()


func _exit_tree() -> void:
	_shipped.cancel()
	_mine.cancel()
	_imports.cancel()


func _process(_delta: float) -> void:
	if _imports.poll():
		_say(_imports.report(), _imports.any_refused())
		_load_section(_mine, user_root)
	if not _sections_loading():
		return
	for section: CardSection in [_shipped, _mine]:
		if section.has_pending_slots():
			section.add_pending_slots(SLOTS_PER_FRAME)
			_focus.link()  # the new cards take their places in the arrows' order
	for section: CardSection in [_shipped, _mine]:
		section.take_loaded(FILLS_PER_FRAME)
	if not _sections_loading():
		_loaded()


func _unhandled_input(event: InputEvent) -> void:
	if _dialogs.open_dialog() != null or _card_menu.visible:
		return
	if event.is_action_pressed("board_actions"):
		var focused := get_viewport().gui_get_focus_owner()
		if focused is LevelCard:
			get_viewport().set_input_as_handled()
			open_card_menu(focused as LevelCard)
	elif event.is_action_pressed("ui_accept") and _refuse_locked(_focused_card()):
		get_viewport().set_input_as_handled()
	elif event.is_action_pressed("ui_cancel"):
		# handled first: the scene change takes this screen out of the tree (no viewport then)
		get_viewport().set_input_as_handled()
		App.go_to_menu()
	elif _is_navigation(event) and get_viewport().gui_get_focus_owner() == null:
		# a mouse click on empty space drops focus: the keys and the pad take it back
		_focus.take_back()
		get_viewport().set_input_as_handled()


## The footer's status line (empty when hidden).
func status_text() -> String:
	return _status.text if _status.visible else ""


## Lists and loads every board file again (shipped and My boards).
func reload() -> void:
	_folder.show_path("Folder: ", LevelSelectWords.shown_path("%s/%s" % [user_root, kind]))
	_load_section(_shipped, BoardLoader.LEVELS_DIR)
	_load_section(_mine, user_root)


## Shows the boards of another My boards folder (the screenshots use a scratch one).
func use_folder(root: String) -> void:
	user_root = root
	reload()


## True while some board file is still loading or being imported.
func is_loading() -> bool:
	return _sections_loading() or _imports.is_busy()


## Lists these load results as the shipped boards' cards (one per file, broken ones greyed),
## at once, and focuses the first playable one.
func show_boards(results: Array[BoardLoadResult]) -> void:
	if kind == BoardLevel.MAZE_NAME:
		results = MazeProgress.sorted(results)
	_shipped.show_results(results)
	_focus.link()
	_loaded()


## Imports board files (a drop on the window, or the file dialog's pick) into My boards off
## the main thread (each is read and checked first, which a large board makes slow), then
## says what happened to each. Files dropped while an import runs wait for it to finish.
func import_files(sources: PackedStringArray) -> void:
	var started := _imports.add(sources, kind, user_root)
	if not started.is_empty():
		_say(started, false)


## Writes the file of `board_path` to `target` (the export dialog's pick) and says so.
func export_board(board_path: String, target: String) -> void:
	var roots: Array[String] = [BoardLoader.LEVELS_DIR + "/", user_root + "/"]
	var error := UserBoards.export_file(board_path, target, roots)
	if error == OK:
		_say("Exported %s to %s." % [board_path.get_file(), target], false)
	else:
		_say("Could not export %s: %s." % [board_path.get_file(), error_string(error)], true)


## Opens the card's own menu (Play, Export a copy…, and Delete… on the player's boards).
func open_card_menu(card: LevelCard) -> void:
	var slot := card.get_parent() as LevelSlot
	if slot == null:
		return
	# a locked maze board or one that did not load offers Play greyed, like its card
	var can_play := card.playable and not card.disabled
	_card_menu.open_for(
		card.board_path, card.get_global_rect(), can_play, slot.is_mine(), card.locked
	)


## The card menu (for tests).
func card_menu() -> CardActionsMenu:
	return _card_menu


## Deletes one of the player's boards (after the dialog's confirmation) and says so.
func delete_board(board_path: String) -> void:
	_focus.keep_place_after_delete(board_path)
	var error := UserBoards.delete_file(board_path, user_root)
	if error == OK:
		_say("Deleted %s from My boards." % board_path.get_file(), false)
	else:
		_say("Could not delete %s: %s." % [board_path.get_file(), error_string(error)], true)
	_load_section(_mine, user_root)


## The cards shown (shipped boards first, then My boards), in order.
func cards() -> Array[Button]:
	return _focus.cards()


## The slots of My boards, in order.
func my_slots() -> Array[LevelSlot]:
	return _mine.slots()


## The first playable card, else the first card, else null.
func first_card() -> Button:
	return _focus.first_card()


func _section(grid: GridContainer, mine: bool) -> CardSection:
	var section := CardSection.new(grid, mine)
	section.kind = kind
	section.slot_added.connect(_connect_slot)
	section.card_filled.connect(_on_card_filled)
	return section


# The list is as wide as the window's content (drawn bigger on a portrait phone) less the
# screen's margins. Not while the screen leaves the tree (a test's window closing resizes it).
func _fit_columns() -> void:
	if not is_inside_tree():
		return
	var margin := $Margin as MarginContainer
	var zoom := ($Margin/PortraitZoom as PortraitZoom).zoomed_by()
	var sides := (
		margin.get_theme_constant(&"margin_left") + margin.get_theme_constant(&"margin_right")
	)
	_focus.fit_columns(get_viewport_rect().size.x / zoom - sides)


func _sections_loading() -> bool:
	return _shipped.is_loading() or _mine.is_loading()


func _import_one(source: String) -> void:
	import_files(PackedStringArray([source]))


# Shows a card saying "Loading…" for every file in `<root>/<kind>/` and starts loading them.
func _load_section(section: CardSection, root: String) -> void:
	var kind_value := BoardLevel.kind_named(kind)
	var paths := BoardLoader.list_files(kind_value, root)
	if section.mine:
		_not_listed = maxi(0, paths.size() - MAX_LISTED)
		paths = paths.slice(0, MAX_LISTED)
	elif kind == BoardLevel.MAZE_NAME:
		paths = MazeCardOrder.in_play_order(paths)
	var jobs: Array[Dictionary] = []
	for path in paths:
		jobs.append({"path": path, "kind": kind_value, "root": root})
	section.start(paths, jobs, load_one, SLOTS_PER_FRAME)
	_focus.link()
	_update_summary()
	_focus.after_listing()


func _connect_slot(slot: LevelSlot) -> void:
	slot.export_requested.connect(_dialogs.ask_export)
	slot.delete_requested.connect(_dialogs.ask_delete)
	slot.card.pressed.connect(func() -> void: App.start_game(kind, slot.card.board_path))
	slot.menu_requested.connect(open_card_menu)


func _on_card_menu_chosen(choice: CardActionsMenu.Choice, board_path: String) -> void:
	var slot := _slot_of(board_path)
	if slot == null:
		return
	match choice:
		CardActionsMenu.Choice.PLAY:
			if slot.card.playable and not slot.card.disabled:
				App.start_game(kind, board_path)
		CardActionsMenu.Choice.EXPORT:
			_dialogs.ask_export(board_path)
		CardActionsMenu.Choice.DELETE:
			if slot.is_mine():
				_dialogs.ask_delete(board_path, slot.shown_name())


func _slot_of(board_path: String) -> LevelSlot:
	var slot := _shipped.slot_of(board_path)
	return slot if slot != null else _mine.slot_of(board_path)


func _on_card_filled() -> void:
	if kind == BoardLevel.MAZE_NAME:
		# at once, not only when all have loaded: a locked board never starts meanwhile
		_show_maze_progress()
		_focus.link()
		_focus.after_reorder()
	_update_summary()


# Everything has loaded: the focus settles (LevelSelectFocus.after_loading).
func _loaded() -> void:
	_update_summary()
	_focus.after_loading()


# Shipped mazes in the order they open, then medals and locks on them; the player's own
# boards get their medals and are never locked.
func _show_maze_progress() -> void:
	MazeCardProgress.apply(MazeCardOrder.sort_grid(_shipped.grid))
	MazeCardProgress.apply(_mine.cards(), false)


func _update_summary() -> void:
	var mine := my_slots().size()
	_my_empty.visible = mine == 0
	_summary.text = LevelSelectWords.summary_of(kind, cards(), mine, _not_listed)


func _focused_card() -> LevelCard:
	return get_viewport().gui_get_focus_owner() as LevelCard


# Enter on a locked maze card: a dull knock and a line saying what opens it (a play trial
# pressed Enter on one and nothing at all happened). False for any other card.
func _refuse_locked(card: LevelCard) -> bool:
	if card == null or not card.locked:
		return false
	_say(LevelSelectWords.locked_line(card.unlock_after), false)
	($UiSounds as UiSounds).refuse()
	return true


# The footer's status line shows only while it has something to say: an empty one left a
# blank band over the keys' hint.
func _say(message: String, is_problem: bool) -> void:
	_status.text = message
	_status.visible = not message.is_empty()
	_status.theme_type_variation = &"WarningLabel" if is_problem else &"HintLabel"


static func _is_navigation(event: InputEvent) -> bool:
	for action: String in ["ui_up", "ui_down", "ui_left", "ui_right"]:
		if event.is_action_pressed(action):
			return true
	return false
