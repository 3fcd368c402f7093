extends Control
## The level select of one game (App.level_select_kind): the shipped boards (levels/<kind>/)
## and the player's own ("My boards", user://boards/<kind>/), one card per file. Files load
## off the main thread (BoardListLoading): cards say "Loading…" and fill in, so a slow or
## hostile file never stops the screen; a board that fails to load is greyed with its error.
## My boards can be imported (button or a file dropped on the window), exported and deleted.
## Shipped maze boards come in the order they open (MazeProgress) with medals and locks.
## The arrows and the d-pad move card to card (CardGridFocus), Enter / A plays, and a card's
## own menu (board_actions: X / Square, or a right click) offers Play, Export and Delete.

const LevelSlot := preload("res://scenes/menu/level_slot.gd")
const MazeCardProgress := preload("res://scenes/menu/maze_card_progress.gd")
const Dialogs := preload("res://scenes/menu/my_boards_dialogs.gd")
const CardActionsMenu := preload("res://scenes/menu/card_actions_menu.gd")
const CardGridFocus := preload("res://scenes/menu/card_grid_focus.gd")
const LevelCard := preload("res://scenes/menu/level_card.gd")
const Words := preload("res://scenes/menu/level_select_words.gd")
const BoardImportQueue := preload("res://scenes/menu/board_import_queue.gd")
## Room between cards, across and down (the grids' separations in the scene).
const CARD_GAP := 22
## At most this many cards in a row, however wide the window.
const MAX_COLUMNS := 4
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

var _loadings: Dictionary = {}  # the grid a loading fills -> its BoardListLoading
var _imports := BoardImportQueue.new()  # imports check and copy off the main thread
var _not_listed := 0  # files in My boards past MAX_LISTED
var _unslotted: Dictionary = {}  # grid -> the listed paths that have no card yet
var _early: Dictionary = {}  # grid -> {path: BoardLoadResult} loaded before its card was made
var _first_focus: Control = null
var _columns := 3
# after a delete: the board whose card takes the focus (the next one), and where the list
# was scrolled to, so the player stays where they were
var _refocus_path := ""
var _kept_scroll := -1

@onready var _title: Label = %TitleLabel
@onready var _summary: Label = %SummaryLabel
@onready var _status: Label = %StatusLabel
@onready var _grid: GridContainer = %Cards
@onready var _my_grid: GridContainer = %MyCards
@onready var _my_empty: Label = %MyBoardsEmpty
@onready var _folder: Label = %FolderLabel
@onready var _back: Button = %BackButton
@onready var _import: Button = %ImportButton
@onready var _dialogs: Dialogs = %Dialogs
@onready var _scroll: ScrollContainer = %Scroll
@onready var _card_menu: CardActionsMenu = %CardMenu
@onready var _hint: Label = %Hint


func _ready() -> void:
	_back.pressed.connect(App.go_to_menu)
	_import.pressed.connect(_dialogs.ask_import)
	_dialogs.import_chosen.connect(_import_one)
	_dialogs.export_chosen.connect(export_board)
	_dialogs.delete_confirmed.connect(delete_board)
	_card_menu.chosen.connect(_on_card_menu_chosen)
	_scroll.resized.connect(_fit_columns)
	get_window().files_dropped.connect(import_files)
	kind = App.level_select_kind
	_imports.titles = TITLES
	_title.text = "%s: choose a board" % TITLES.get(kind, kind.capitalize())
	_status.text = ""
	_hint.text = (
		"Arrows / D-pad: choose a board · Enter / A: play · %s: its menu · Esc / B: back"
		% Words.menu_keys()
	)
	reload()


func _exit_tree() -> void:
	for loading: BoardListLoading in _loadings.values():
		loading.cancel()
	_loadings.clear()
	_imports.cancel()


func _process(_delta: float) -> void:
	if _imports.poll():
		_say(_imports.report(), _imports.any_refused())
		_load_section(_my_grid, user_root)
	if _loadings.is_empty():
		return
	for grid: GridContainer in _unslotted.keys():
		_add_slots(grid)
	for grid: GridContainer in _loadings.keys():
		var loading: BoardListLoading = _loadings[grid]
		for done in loading.take_finished(FILLS_PER_FRAME):
			var path: String = done["path"]
			var result: BoardLoadResult = done["result"]
			var unslotted: Array[String] = _unslotted.get(grid, [] as Array[String])
			if unslotted.has(path):
				var early: Dictionary = _early.get_or_add(grid, {})
				early[path] = result
			else:
				_fill(grid, path, result)
		if not loading.is_busy() and not _unslotted.has(grid):
			_loadings.erase(grid)
	if _loadings.is_empty():
		_loaded()


func _unhandled_input(event: InputEvent) -> void:
	if _dialogs.open_dialog() != null or _card_menu.visible:
		return
	if event.is_action_pressed("board_actions"):
		var focused := get_viewport().gui_get_focus_owner()
		if focused is LevelCard:
			get_viewport().set_input_as_handled()
			open_card_menu(focused as LevelCard)
	elif event.is_action_pressed("ui_cancel"):
		# handled first: the scene change takes this screen out of the tree (no viewport then)
		get_viewport().set_input_as_handled()
		App.go_to_menu()
	elif _is_navigation(event) and get_viewport().gui_get_focus_owner() == null:
		# a mouse click on empty space drops focus: the keys and the pad take it back
		var first := first_card()
		(first if first != null else _back).grab_focus()
		get_viewport().set_input_as_handled()


## Lists and loads every board file again (shipped and My boards).
func reload() -> void:
	_folder.text = "Folder: %s" % Words.shown_path("%s/%s" % [user_root, kind])
	_load_section(_grid, BoardLoader.LEVELS_DIR)
	_load_section(_my_grid, user_root)


## Shows the boards of another My boards folder (the screenshots use a scratch one).
func use_folder(root: String) -> void:
	user_root = root
	reload()


## True while some board file is still loading or being imported.
func is_loading() -> bool:
	return not _loadings.is_empty() or _imports.is_busy()


## Lists these load results as the shipped boards' cards (one per file, broken ones greyed),
## at once, and focuses the first playable one.
func show_boards(results: Array[BoardLoadResult]) -> void:
	if _loadings.has(_grid):
		_cancel(_grid)
		_loadings.erase(_grid)
	_clear(_grid)
	if kind == BoardLevel.MAZE_NAME:
		results = MazeProgress.sorted(results)
	for result in results:
		_add_slot(_grid, result.path)
		_fill(_grid, result.path, result)
	_link_focus()
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
	_card_menu.open_for(card.board_path, card.get_global_rect(), can_play, slot.is_mine())


## The card menu (for tests).
func card_menu() -> CardActionsMenu:
	return _card_menu


## Deletes one of the player's boards (after the dialog's confirmation) and says so.
func delete_board(board_path: String) -> void:
	_keep_place_after_delete(board_path)
	var error := UserBoards.delete_file(board_path, user_root)
	if error == OK:
		_say("Deleted %s from My boards." % board_path.get_file(), false)
	else:
		_say("Could not delete %s: %s." % [board_path.get_file(), error_string(error)], true)
	_load_section(_my_grid, user_root)


## The cards shown (shipped boards first, then My boards), in order.
func cards() -> Array[Button]:
	var result: Array[Button] = []
	for grid: GridContainer in [_grid, _my_grid]:
		for slot: Node in grid.get_children():
			if slot is LevelSlot and not slot.is_queued_for_deletion():
				result.append((slot as LevelSlot).card)
	return result


## The slots of My boards, in order.
func my_slots() -> Array[LevelSlot]:
	var result: Array[LevelSlot] = []
	for slot in _my_grid.get_children():
		if slot is LevelSlot and not slot.is_queued_for_deletion():
			result.append(slot as LevelSlot)
	return result


## The first playable card, else the first card, else null.
func first_card() -> Button:
	var all := cards()
	for card in all:
		if not card.disabled:
			return card
	return all[0] if not all.is_empty() else null


func _grid_first_card() -> Button:
	for slot in _grid.get_children():
		if slot is LevelSlot:
			return (slot as LevelSlot).card
	return null


func _import_one(source: String) -> void:
	import_files(PackedStringArray([source]))


# Shows a card saying "Loading…" for every file in `<root>/<kind>/` and starts loading them.
func _load_section(grid: GridContainer, root: String) -> void:
	if _loadings.has(grid):
		_cancel(grid)
	_clear(grid)
	var kind_value := BoardLevel.kind_named(kind)
	var jobs: Array[Dictionary] = []
	var paths := BoardLoader.list_files(kind_value, root)
	if grid == _my_grid:
		_not_listed = maxi(0, paths.size() - MAX_LISTED)
		paths = paths.slice(0, MAX_LISTED)
	if kind == BoardLevel.MAZE_NAME and grid == _grid:
		paths = _in_maze_order(paths)
	for path in paths:
		jobs.append({"path": path, "kind": kind_value, "root": root})
	_unslotted[grid] = paths
	_early.erase(grid)
	_add_slots(grid)
	_loadings[grid] = BoardListLoading.new(jobs, load_one)
	_update_summary()
	if _refocus_path != "":
		_take_place_back()
	elif not is_instance_valid(_first_focus):
		_first_focus = first_card() if first_card() != null else _import
		_first_focus.grab_focus()


# Makes the next SLOTS_PER_FRAME cards of `grid` (filled at once when their file loaded first).
func _add_slots(grid: GridContainer) -> void:
	var paths: Array[String] = _unslotted.get(grid, [] as Array[String])
	var count := mini(SLOTS_PER_FRAME, paths.size())
	var early: Dictionary = _early.get(grid, {})
	for path: String in paths.slice(0, count):
		_add_slot(grid, path)
		if early.has(path):
			var result: BoardLoadResult = early[path]
			_fill(grid, path, result)
			early.erase(path)
	if count == paths.size():
		_unslotted.erase(grid)
	else:
		_unslotted[grid] = paths.slice(count)
	_link_focus()  # the new cards take their places in the arrows' order


func _cancel(grid: GridContainer) -> void:
	var loading: BoardListLoading = _loadings[grid]
	loading.cancel()


func _add_slot(grid: GridContainer, path: String) -> void:
	var slot := LevelSlot.new(path, grid == _my_grid)
	slot.export_requested.connect(_dialogs.ask_export)
	slot.delete_requested.connect(_dialogs.ask_delete)
	slot.card.pressed.connect(func() -> void: App.start_game(kind, slot.card.board_path))
	slot.card.gui_input.connect(_on_card_gui_input.bind(slot.card))
	grid.add_child(slot)


func _on_card_gui_input(event: InputEvent, card: LevelCard) -> void:
	var click := event as InputEventMouseButton
	if click != null and click.pressed and click.button_index == MOUSE_BUTTON_RIGHT:
		card.grab_focus()
		open_card_menu(card)
		card.accept_event()


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
	for grid: GridContainer in [_grid, _my_grid]:
		for slot in grid.get_children():
			if slot is LevelSlot and (slot as LevelSlot).card.board_path == board_path:
				return slot as LevelSlot
	return null


# As many columns as the list is wide (both sections alike, so their cards line up), then
# the arrows' neighbours again.
func _fit_columns() -> void:
	var card_width := LevelCard.CARD_SIZE.x + CARD_GAP
	var fits := floori((_scroll.size.x - 16.0 + CARD_GAP) / card_width)
	var columns := clampi(fits, 1, MAX_COLUMNS)
	if columns == _columns:
		return
	_columns = columns
	_grid.columns = columns
	_my_grid.columns = columns
	_link_focus()


func _link_focus() -> void:
	var sections: Array = []
	for grid: GridContainer in [_grid, _my_grid]:
		var section: Array[Control] = []
		for slot in grid.get_children():
			if slot is LevelSlot and not slot.is_queued_for_deletion():
				section.append((slot as LevelSlot).card)
		sections.append(section)
	CardGridFocus.link(sections, _columns)


# Before a delete: remember the card after the deleted one (or before it, for the last) and
# the scroll, so the list does not jump back to the top.
func _keep_place_after_delete(board_path: String) -> void:
	var mine := my_slots()
	_refocus_path = ""
	for i in mine.size():
		if mine[i].card.board_path == board_path:
			var neighbour := i + 1 if i + 1 < mine.size() else i - 1
			if neighbour >= 0:
				_refocus_path = mine[neighbour].card.board_path
	if _refocus_path == "":
		_refocus_path = board_path  # none left: the Import button takes the focus
	_kept_scroll = _scroll.scroll_vertical


func _take_place_back() -> void:
	var slot := _slot_of(_refocus_path)
	(slot.card if slot != null else _import as Control).grab_focus()
	_scroll.set_deferred("scroll_vertical", _kept_scroll)
	_refocus_path = ""


func _fill(grid: GridContainer, path: String, result: BoardLoadResult) -> void:
	for slot in grid.get_children():
		if slot is LevelSlot and (slot as LevelSlot).card.board_path == path:
			(slot as LevelSlot).fill(result, Words.best_text(result, kind))
	if kind == BoardLevel.MAZE_NAME:
		# at once, not only when all have loaded: a locked board never starts meanwhile
		_show_maze_progress()
		_link_focus()
	_update_summary()


# Everything has loaded: the first playable card takes the focus the loading card held.
func _loaded() -> void:
	_update_summary()
	var focused := get_viewport().gui_get_focus_owner()
	var stuck := focused == _first_focus and focused is Button and (focused as Button).disabled
	if focused == null or stuck:
		var first := first_card()
		(first if first != null else _back).grab_focus()
	if get_viewport().gui_get_focus_owner() == _grid_first_card():
		# the first row from its top, not scrolled to wherever the loading card sat
		_scroll.set_deferred("scroll_vertical", 0)
	_first_focus = get_viewport().gui_get_focus_owner()


# Shipped mazes in the order they open (by the ids loaded), then medals and locks on them;
# the player's own boards get their medals and are never locked.
func _show_maze_progress() -> void:
	var slots: Array[LevelSlot] = []
	for slot in _grid.get_children():
		if slot is LevelSlot:
			slots.append(slot as LevelSlot)
	slots.sort_custom(
		func(a: LevelSlot, b: LevelSlot) -> bool: return _slot_rank(a) < _slot_rank(b)
	)
	var shipped: Array[Button] = []
	for i in slots.size():
		_grid.move_child(slots[i], i)
		shipped.append(slots[i].card)
	MazeCardProgress.apply(shipped)
	var mine: Array[Button] = []
	for slot in my_slots():
		mine.append(slot.card)
	MazeCardProgress.apply(mine, false)


# A slot's place in the play order; its index breaks ties, so the sort keeps listed order.
static func _slot_rank(slot: LevelSlot) -> int:
	var card := slot.card
	var board_id := card.level.board_id if card.level != null else ""
	return MazeProgress.rank(board_id) * 10000 + slot.get_index()


# Shipped maze files before they load, in the order their ids (maze_<file name>) open.
static func _in_maze_order(paths: Array[String]) -> Array[String]:
	var keyed: Array = []
	for i in paths.size():
		var guessed_id := "maze_" + paths[i].get_file().get_basename()
		keyed.append([MazeProgress.rank(guessed_id) * 10000 + i, paths[i]])
	keyed.sort_custom(func(a: Array, b: Array) -> bool: return a[0] < b[0])
	var ordered: Array[String] = []
	for entry: Array in keyed:
		ordered.append(str(entry[1]))
	return ordered


# Frees the grid's slots at once (never called from one of their own signals).
func _clear(grid: GridContainer) -> void:
	for child in grid.get_children():
		child.free()


func _update_summary() -> void:
	var total := 0
	var broken := 0
	var waiting := 0
	var locked := 0
	for card: Button in cards():
		total += 1
		waiting += 1 if card.get("loading") else 0
		broken += 1 if not card.get("playable") and not card.get("loading") else 0
		locked += 1 if card.get("locked") else 0
	var mine := my_slots().size()
	_my_empty.visible = mine == 0
	_summary.text = Words.summary(kind, total, mine, waiting, broken, locked, _not_listed)


func _say(message: String, is_problem: bool) -> void:
	_status.text = message
	_status.theme_type_variation = &"WarningLabel" if is_problem else &"HintLabel"


static func _is_navigation(event: InputEvent) -> bool:
	for action: String in ["ui_up", "ui_down", "ui_left", "ui_right"]:
		if event.is_action_pressed(action):
			return true
	return false
