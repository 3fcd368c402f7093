class_name MazeProgress
extends RefCounted
## The order the shipped maze boards open in: each opens once the one before it has been
## finished in either mode (the "Unlock all maze boards" setting opens them all). Boards not
## in the order (a designer's own) are always open and listed after them.

## Shipped boards from the first to open to the last: one ball, then two, then the
## four-ball boards from the easiest to the hardest by the maze analysis' difficulty (the
## pilot's seconds of hard-mode play per win, `--analyze=maze --runs=5`; README lists them).
const ORDER: Array[String] = [
	"maze_first_roll",  # 10.9 s a win (maze rules 4, --runs=5)
	"maze_two_together",  # 16.4
	"maze_cloister",  # 13.8 (eased: two holes, one more loop; the first of four balls)
	"maze_garden",  # 10.8 (trial 8: a wall at each turn; was 18.5 with two part-way stops)
	"maze_switchbacks",  # 19.1 (its card teaches the small tilt)
	"maze_long_hall",  # 25.2
	"maze_labyrinth",  # 25.5
	"maze_crossroads",  # 26.6
	"maze_catacombs",  # 28.0
	"maze_classic",  # 30.2
	"maze_tower",  # 38.3
	"maze_courtyards",  # 45.9
	"maze_the_deep",  # 55.6
	"maze_undercroft",  # no hard win in 5 runs under rules 4 (82.6 under 3: ten holes)
]


## The shipped board that opens after `board_id` ("" after the last one or a board not in
## the order).
static func next_of(board_id: String) -> String:
	var at := ORDER.find(board_id)
	return ORDER[at + 1] if at >= 0 and at + 1 < ORDER.size() else ""


## The file of a shipped board id ("maze_garden" → res://levels/maze/garden.board).
static func shipped_path(board_id: String) -> String:
	return "res://levels/maze/%s.board" % board_id.trim_prefix("maze_")


## The file of the shipped board that opens after `board_id` ("" after the last, for the
## player's own boards, or when that file is missing).
static func next_path(board_id: String) -> String:
	var next_id := next_of(board_id)
	if next_id.is_empty():
		return ""
	var path := shipped_path(next_id)
	return path if FileAccess.file_exists(path) else ""


## Where `board_id` comes in the order (boards not in it come after every one that is).
static func rank(board_id: String) -> int:
	var at := ORDER.find(board_id)
	return at if at >= 0 else ORDER.size()


## The load results in the order boards open; broken files and other boards keep their
## listed order after the shipped ones.
static func sorted(results: Array[BoardLoadResult]) -> Array[BoardLoadResult]:
	var keyed: Array = []
	for i in results.size():
		var result := results[i]
		var key := rank(result.level.board_id) if result.ok() else ORDER.size()
		keyed.append([key, i, result])
	keyed.sort_custom(
		func(a: Array, b: Array) -> bool: return a[0] < b[0] or (a[0] == b[0] and a[1] < b[1])
	)
	var out: Array[BoardLoadResult] = []
	for entry: Array in keyed:
		var result: BoardLoadResult = entry[2]
		out.append(result)
	return out


## For boards listed in `board_ids` (in play order), whether each is locked: a board in the
## order is locked until the board before it in the list is finished (`finished` holds the
## ids finished in either mode). Nothing is locked when `unlock_all`.
static func locks(board_ids: Array[String], finished: Dictionary, unlock_all: bool) -> Array[bool]:
	var locked: Array[bool] = []
	var previous_done := true
	for board_id in board_ids:
		var ranked := rank(board_id) < ORDER.size()
		locked.append(ranked and not unlock_all and not previous_done)
		if ranked:
			previous_done = finished.has(board_id)
	return locked
