class_name MazeHints
extends RefCounted
## What the maze screen tells the player in words: the controls line and the hints under
## its notes. Every key is named as the player has bound it (KeyNames), so the words stay
## true after a remap.

## A space that never breaks a line.
const NBSP := "\u00a0"
## Between two items of the controls line: plain spaces, wide enough to read as a gap.
const ITEM_GAP := "    "
## What to try on the first boards after First Roll (whose own hint says how tilting works),
## in easy mode, in place of the hard-mode invitation (the win card still makes it): a blind
## trial found the jump to four balls on boards 3 to 5 steep with no hint of how to go about it.
const TIPS := {
	"maze_two_together": "Tip: let both balls stop against a wall before you tilt the next way.",
	"maze_cloister": "Tip: a ball in the dip stays there, so bring the others in one by one.",
	# trial 8: Garden Path's part-way stops were a wall after Cloister; it now has a wall at
	# each turn, and the small tilt's lesson comes with Switchbacks, which needs it
	"maze_garden": "Tip: hold each tilt until the balls stop: every run ends at your next turn.",
	"maze_switchbacks": "Tip: tap a key, or hold Shift, to stop a ball part-way along a corridor.",
}

## The controls line's first line: how the keys and the mouse tilt the board.
const TILT_LINE := "Tap a key to nudge, hold to roll, or drag the board"


## The controls line under the side panel. Each "Space reset" item holds together (its
## spaces don't break) and the items are set apart by plain spaces (ITEM_GAP), which a wrapped
## line drops at its ends: a line never starts with a stray "· Escape pause" (a play trial)
## nor ends on a dangling "E easy ·" (trial 6), as a dot between items did on one side.
static func controls() -> String:
	var items := PackedStringArray()
	for item: String in [
		"%s fine tilt" % KeyNames.of(&"tilt_fine", "the fine key"),
		"%s reset" % _reset(),
		"%s hard" % _hard(),
		"%s easy" % _easy(),
		"%s pause" % KeyNames.of(&"pause", "the pause key"),
	]:
		items.append(item.replace(" ", NBSP))
	# trial 9: a tap is a fixed nudge and a hold rolls on; a drag on the board tilts it
	return TILT_LINE + "\n" + ITEM_GAP.join(items)


## The headline before the first tilt. Two phrases, each held by no-break spaces and the
## two joined by a plain one: a narrow column breaks it only as "Tilt the board / to start!"
## (trial 7 read "Tilt the board to star / t!" when the whole line was one unbreakable word).
static func tilt_to_start() -> String:
	return "Tilt the board".replace(" ", NBSP) + " " + "to start!".replace(" ", NBSP)


## The line in its place before there is a best run to race (as long, so the note keeps its
## height when the ghost comes).
static func no_ghost_yet() -> String:
	return "Finish to race your best run."


## The hint under "Tilt the board to start!" in easy or `hard` mode, on a board of `balls`
## balls and `holes` black holes (a one-ball board is the first: it says how tilting works;
## hard mode on a board without holes says it plays the same).
## `board_id`'s tip (TIPS) takes the easy hint's last place on the first boards.
static func start(hard: bool, balls: int = 4, holes: int = 1, board_id := "") -> String:
	if hard and holes == 0:
		return (
			"This board has no black holes, so hard mode is the same as easy."
			+ " Back to easy mode? Press%s%s" % [NBSP, _easy()]
		)
	if hard:
		return "Hard mode: avoid the black holes. Back to easy mode? Press%s%s" % [NBSP, _easy()]
	if balls == 1:
		return "Tap or hold the arrows, or drag the board: the ball rolls downhill, into the dip."
	if TIPS.has(board_id):
		return "Roll every ball into the round dip. %s" % TIPS[board_id]
	if holes == 0:
		return "Roll every ball into the round dip."
	return "Roll every ball into the round dip. Ready for hard mode? Press%s%s" % [NBSP, _hard()]


## The start hint's last line: the ghost's when `has_ghost`, and before there is a ghost one
## as long (while the ghost is shown at all), so the note keeps its height (and the panel its
## layout) from the first attempt to the next. Empty, or a line break and the line.
static func ghost_line(has_ghost: bool, ghost_shown: bool) -> String:
	if has_ghost:
		return "\n" + ghost()
	return "\n" + no_ghost_yet() if ghost_shown else ""


## The hint on a board opened from a hard-mode run that has no black holes (so it plays in
## easy mode).
static func easy_here() -> String:
	return "No black holes on this board, so it plays in easy mode. Roll every ball into the dip."


## The hint when H is pressed on a board without black holes (it has no hard mode).
static func no_hard_mode() -> String:
	return "This board has no black holes, so it has no hard mode."


## The line under the start hint when the best run's ghost rolls beside the balls (a play
## trial took the pale ball for one more ball of its own; the ghost is blue glass now).
static func ghost() -> String:
	return "See-through blue balls replay your best run."


## The hint under "Congrats, you did it!" (hard mode has nothing harder to offer, and a board
## without black holes has no hard mode worth asking for).
static func won(hard: bool, holes: int = 1) -> String:
	return "" if hard or holes == 0 else "Press%s%s for hard mode" % [NBSP, _hard()]


## The note and its hint when a ball falls into a black hole: the run can't be won any
## more (every ball must reach the dip), and how to go again.
static func lost() -> PackedStringArray:
	return PackedStringArray(
		[
			"A ball fell into a black hole: this run can't be won now.",
			(
				"Retry, or press%s%s to start again. Back to easy? Press%s%s"
				% [NBSP, _reset(), NBSP, _easy()]
			),
		]
	)


## The count once a ball is lost, on the panel and the card alike: "2 of 4 balls left".
static func balls_left(left: int, total: int) -> String:
	return "%d of %d balls left" % [left, total]


static func _reset() -> String:
	return KeyNames.of(&"maze_reset", "the reset key")


static func _hard() -> String:
	return KeyNames.of(&"maze_hard_mode", "the hard-mode key")


static func _easy() -> String:
	return KeyNames.of(&"maze_easy_mode", "the easy-mode key")
