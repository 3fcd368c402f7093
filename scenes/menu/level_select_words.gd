class_name LevelSelectWords
extends RefCounted
## What the level select says, as a player reads it: the summary line over the cards, a
## card's best result, the folder's real path, the keys line and the keys that open a
## card's menu.


## The line over the cards: how many boards, of your own, loading, broken, locked, and how
## many files were left out of My boards. `kind` names the game's folder when there are none.
static func summary(
	kind: String, total: int, mine: int, waiting: int, broken: int, locked: int, not_listed: int
) -> String:
	if total == 0:
		return "No boards found in levels/%s/ or in My boards." % kind
	var text := "%d board%s" % [total, "" if total == 1 else "s"]
	if mine > 0:
		text += " (%d of your own)" % mine
	if waiting > 0:
		text += ", %d loading…" % waiting
	if broken > 0:
		text += ", %d could not be loaded (greyed)" % broken
	if locked > 0:
		text += ", %d locked (finish a board to unlock the next)" % locked
	if not_listed > 0:
		text += "; %d more files not listed" % not_listed  # short: the line has one row
	return text


## The summary line for these cards (loading, broken and locked ones counted), of which
## `mine` are the player's own.
static func summary_of(kind: String, cards: Array[Button], mine: int, not_listed: int) -> String:
	var broken := 0
	var waiting := 0
	var locked := 0
	for card in cards:
		waiting += 1 if card.get("loading") else 0
		broken += 1 if not card.get("playable") and not card.get("loading") else 0
		locked += 1 if card.get("locked") else 0
	return summary(kind, cards.size(), mine, waiting, broken, locked, not_listed)


## The keys line under the cards.
static func keys_hint() -> String:
	return (
		"Arrows / D-pad: choose a board · Enter / A: play · %s: its menu · Esc / B: back"
		% menu_keys()
	)


## A card's best result on the board `result` loaded: maze times per mode, or pachinko balls
## won (with "Cleared!" once its goal was reached);
## "" when there is none yet or the board did not load.
static func best_text(result: BoardLoadResult, kind: String) -> String:
	if not result.ok():
		return ""
	var board_id := result.level.board_id
	if kind == BoardLevel.MAZE_NAME:
		var easy := App.best_maze_time(board_id, false)
		var hard := App.best_maze_time(board_id, true)
		if easy <= 0.0 and hard <= 0.0:
			return ""
		if hard <= 0.0:
			return "Best time: %s" % MazeWinSummary.clock(easy)
		if easy <= 0.0:
			return "Best time (hard): %s" % MazeWinSummary.clock(hard)
		# each mode's best on one line of the card, under that mode's medal
		return "Easy %s · Hard %s" % [MazeWinSummary.clock(easy), MazeWinSummary.clock(hard)]
	var balls := App.best_pachinko_balls(board_id)
	var best := "Most won: %d balls" % balls if balls >= 0 else ""
	# a machine whose tray the player filled to its goal (PachinkoGoals) says so first
	return "Cleared! " + best if App.has_cleared_pachinko(board_id) else best


## Players know their files by the real path, not by user://.
static func shown_path(path: String) -> String:
	return path.replace("user://", OS.get_user_data_dir() + "/")


## The card menu's first key and first pad button as the player has them bound.
static func menu_keys() -> String:
	var names := PackedStringArray()
	for wanted: bool in [true, false]:
		for event in App.settings.events_for("board_actions"):
			if (event is InputEventKey) == wanted:
				names.append(InputEventCodec.describe(event))
				break
	if names.size() == 2 and names[1].begins_with(names[0] + " /"):
		names.remove_at(0)  # the X key and the pad's "X / Square" read as one
	return " / ".join(names) if not names.is_empty() else "Right click"


## What Enter on a locked maze card says: the board whose finish opens it.
static func locked_line(unlock_after: String) -> String:
	if unlock_after.is_empty():
		return "This board is locked"
	return "Finish %s to unlock this board" % unlock_after
