extends RefCounted
## A pachinko board for a test's games, with an in-memory save: begin() asks App for the
## board and swaps App.save_data for a fresh one that is never written, returning the
## player's; end() puts the player's save back and the classic board (what the next test
## expects). Tests that call App.request_board must restore the classic board.

const CLASSIC := "res://levels/pachinko/classic.board"
## The board most pachinko rule tests play: it has reels, a jackpot and an attacker.
const FEVER := "res://levels/pachinko/fever.board"


## Asks for `board` and swaps in an in-memory save; returns the player's save.
static func begin(board: String = FEVER) -> RefCounted:
	var kept: RefCounted = App.save_data
	App.save_data = SaveData.new()  # in memory only: never written
	App.request_board("pachinko", board)
	return kept


## Puts the player's save `kept` back and asks for the classic board again.
static func end(kept: RefCounted) -> void:
	App.save_data = kept
	App.request_board("pachinko", CLASSIC)


## A game of the board `name` (levels/pachinko/NAME.board) added to `test`, freed after it.
static func game(test: GutTest, name: String) -> PachinkoGame:
	App.request_board("pachinko", "res://levels/pachinko/%s.board" % name)
	var opened := (load("res://scenes/pachinko/pachinko_game.tscn") as PackedScene).instantiate()
	test.add_child_autofree(opened)
	return opened as PachinkoGame
