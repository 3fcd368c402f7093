class_name MazeCardProgress
extends RefCounted
## Puts maze progression on the level select's cards: each card's medals (from the best
## time per mode and the board's medal times) and, unless every board is unlocked in the
## settings, a lock on boards whose predecessor is not finished yet.


## Marks every loaded maze card in `cards` (in play order, see MazeProgress.sorted) with its
## medals; with `lockable` (the shipped boards) also locks the boards not open yet. The
## player's own boards pass false: they are always open, even one that copies a shipped id.
static func apply(cards: Array[Button], lockable: bool = true) -> void:
	var ids: Array[String] = []
	var finished := {}
	var shown: Array[LevelCard] = []
	for button in cards:
		var card := button as LevelCard
		if card == null or not card.playable:
			continue
		var board_id := card.level.board_id
		ids.append(board_id)
		shown.append(card)
		if App.best_maze_time(board_id, false) > 0.0 or App.best_maze_time(board_id, true) > 0.0:
			finished[board_id] = true
	var unlock_all := App.settings.unlock_all_boards or not lockable
	var locks := MazeProgress.locks(ids, finished, unlock_all)
	var previous := ""
	for i in shown.size():
		var card := shown[i]
		var board_id := ids[i]
		var easy := Medals.medal(card.level, false, App.best_maze_time(board_id, false))
		var hard := Medals.medal(card.level, true, App.best_maze_time(board_id, true))
		var hint := "Locked: finish %s first" % previous
		card.show_progress(easy, hard, locks[i], hint)
		card.unlock_after = previous if locks[i] else ""
		var slot := card.get_parent() as LevelSlot
		if slot != null:
			slot.show_locked(locks[i])
		if MazeProgress.rank(board_id) < MazeProgress.ORDER.size():
			previous = card.level.display_name
