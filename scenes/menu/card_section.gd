class_name CardSection
extends RefCounted
## One section of the level select: a grid of card slots (the shipped boards, or My boards)
## and the off-thread loading (BoardListLoading) that fills it. A card is made for every
## listed file, a few a frame, saying "Loading…" until its file has loaded; a file that
## loads before its card is made waits here and fills the card as it is made.

## A slot was made and put in the grid (the screen connects its buttons).
signal slot_added(slot: LevelSlot)
## A loaded board was put on its card (or its card was gone by then).
signal card_filled

## The grid the slots go in.
var grid: GridContainer = null
## True for My boards: the player's own boards, which may be deleted.
var mine := false
## The game whose boards are listed (a name of BoardLevel.KIND_NAMES), for the best lines.
var kind := BoardLevel.PACHINKO_NAME

var _loading: BoardListLoading = null
var _unslotted: Array[String] = []  # listed paths that have no slot yet, in order
var _early: Dictionary = {}  # path -> BoardLoadResult loaded before its slot was made


## A section over `section_grid`; `is_mine`: the player's own boards.
func _init(section_grid: GridContainer, is_mine: bool) -> void:
	grid = section_grid
	mine = is_mine


## Drops the cards and lists `paths` again: a "Loading…" card for each (the first
## `slots_now` at once, the rest through add_pending_slots) while `jobs` load off the main
## thread through `load_one` (see BoardListLoading).
func start(
	paths: Array[String], jobs: Array[Dictionary], load_one: Callable, slots_now: int
) -> void:
	cancel()
	clear()
	_unslotted = paths.duplicate()
	_early.clear()
	add_pending_slots(slots_now)
	_loading = BoardListLoading.new(jobs, load_one)


## Drops the cards and shows these finished loads at once (no loading).
func show_results(results: Array[BoardLoadResult]) -> void:
	cancel()
	clear()
	_unslotted.clear()
	_early.clear()
	for result in results:
		_add_slot(result.path)
		fill(result.path, result)


## Makes up to `most` of the cards still to be made, filling those whose file already loaded.
func add_pending_slots(most: int) -> void:
	var count := mini(most, _unslotted.size())
	for path: String in _unslotted.slice(0, count):
		_add_slot(path)
		if _early.has(path):
			var result: BoardLoadResult = _early[path]
			_early.erase(path)
			fill(path, result)
	_unslotted = _unslotted.slice(count)


## True while some listed file has no card yet.
func has_pending_slots() -> bool:
	return not _unslotted.is_empty()


## Puts up to `most` finished loads on their cards (or keeps them until their card is made).
func take_loaded(most: int) -> void:
	if _loading == null:
		return
	for done in _loading.take_finished(most):
		var path: String = done["path"]
		var result: BoardLoadResult = done["result"]
		if _unslotted.has(path):
			_early[path] = result
		else:
			fill(path, result)
	if not _loading.is_busy() and _unslotted.is_empty():
		_loading = null


## True from start until every listed file is on its card.
## Boards loaded before their card was made, kept until their card comes.
func waiting_results() -> int:
	return _early.size()


func is_loading() -> bool:
	return _loading != null


## Stops the loading (the files still queued are never read).
func cancel() -> void:
	if _loading != null:
		_loading.cancel()
		_loading = null


## Puts a finished load on the card of `path`.
func fill(path: String, result: BoardLoadResult) -> void:
	var slot := slot_of(path)
	if slot != null:
		slot.fill(result, LevelSelectWords.best_text(result, kind))
	card_filled.emit()


## The slots shown, in order.
func slots() -> Array[LevelSlot]:
	var result: Array[LevelSlot] = []
	for child in grid.get_children():
		if child is LevelSlot and not child.is_queued_for_deletion():
			result.append(child as LevelSlot)
	return result


## The cards shown, in order.
func cards() -> Array[Button]:
	var result: Array[Button] = []
	for slot in slots():
		result.append(slot.card)
	return result


## The slot of the board file at `board_path`, or null.
func slot_of(board_path: String) -> LevelSlot:
	for slot in slots():
		if slot.card.board_path == board_path:
			return slot
	return null


## Frees the slots at once (never called from one of their own signals).
func clear() -> void:
	for child in grid.get_children():
		child.free()


func _add_slot(path: String) -> void:
	var slot := LevelSlot.new(path, mine)
	grid.add_child(slot)
	slot_added.emit(slot)
