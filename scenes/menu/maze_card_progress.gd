extends RefCounted
## Puts maze progression on the level select's cards: each card's medals (from the best
## time per mode and the board's medal times) and, unless every board is unlocked in the
## settings, a lock on boards whose predecessor is not finished yet.

const LevelCard := preload("res://scenes/menu/level_card.gd")


## Marks every maze card in `cards` (in play order, see MazeProgress.sorted).
static func apply(cards: Array[Button]) -> void:
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
		if best_time(board_id, false) > 0.0 or best_time(board_id, true) > 0.0:
			finished[board_id] = true
	var locks := MazeProgress.locks(ids, finished, App.settings.unlock_all_boards)
	var previous := ""
	for i in shown.size():
		var card := shown[i]
		var board_id := ids[i]
		var easy := Medals.medal(card.level, false, best_time(board_id, false))
		var hard := Medals.medal(card.level, true, best_time(board_id, true))
		var hint := "Locked: finish %s first" % previous
		card.show_progress(easy, hard, locks[i], hint)
		if MazeProgress.rank(board_id) < MazeProgress.ORDER.size():
			previous = card.level.display_name


## The player's best time on `board_id` in hard or easy mode, -1 when never finished.
## SaveData keeps a best time per board and mode (`best_maze_time(board_id, hard)`); a save
## format with one time per board answers for both modes.
static func best_time(board_id: String, hard: bool) -> float:
	var seconds: float = -1.0
	if App.get_method_argument_count(&"best_maze_time") >= 2:
		seconds = App.call(&"best_maze_time", board_id, hard)
	else:
		seconds = App.call(&"best_maze_time", board_id)
	return seconds
