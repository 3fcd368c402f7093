class_name MazeCardOrder
extends RefCounted
## The order of the shipped maze cards on the level select: the order the boards open in
## (MazeProgress), first guessed from the file names before they load, then from the board
## ids loaded. Boards outside the play order keep their listed order after the others.

# a rank counts for more than any place in a list, so a sort by rank keeps ties in order
const RANK_STEP := 10000


## Shipped maze files before they load, in the order their ids (maze_<file name>) open.
static func in_play_order(paths: Array[String]) -> Array[String]:
	var keyed: Array = []
	for i in paths.size():
		var guessed_id := "maze_" + paths[i].get_file().get_basename()
		keyed.append([MazeProgress.rank(guessed_id) * RANK_STEP + i, paths[i]])
	keyed.sort_custom(func(a: Array, b: Array) -> bool: return a[0] < b[0])
	var ordered: Array[String] = []
	for entry: Array in keyed:
		ordered.append(str(entry[1]))
	return ordered


## Moves the slots of `grid` into the order their loaded boards open in and returns their
## cards in that order.
static func sort_grid(grid: GridContainer) -> Array[Button]:
	var slots: Array[LevelSlot] = []
	for child in grid.get_children():
		if child is LevelSlot:
			slots.append(child as LevelSlot)
	slots.sort_custom(func(a: LevelSlot, b: LevelSlot) -> bool: return _rank(a) < _rank(b))
	var cards: Array[Button] = []
	for i in slots.size():
		grid.move_child(slots[i], i)
		cards.append(slots[i].card)
	return cards


# A slot's place in the play order; its index breaks ties, so the sort keeps listed order.
static func _rank(slot: LevelSlot) -> int:
	var card := slot.card
	var board_id := card.level.board_id if card.level != null else ""
	return MazeProgress.rank(board_id) * RANK_STEP + slot.get_index()
