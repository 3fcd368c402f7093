extends GutTest
## Small things a blind play trial found on the pachinko screen: the side panel jumped when
## the "Best" line first appeared (the stats' Best session line already has its place, so
## nothing is added under it), and Windmills' rules card drew its pocket red beside the
## board's blue ones (the icon takes the board's machine's colours, as the board does).

const GAME := preload("res://scenes/pachinko/pachinko_game.tscn")
const SaveData := preload("res://scripts/app/save_data.gd")
const PieceIcon := preload("res://scenes/pachinko/legend/piece_icon.gd")
const BoardPieces := preload("res://scenes/pachinko/legend/board_pieces.gd")
const StretchedWindow := preload("res://tests/integration/stretched_window.gd")

var _kept_save: SaveData


func before_each() -> void:
	_kept_save = App.save_data
	App.save_data = SaveData.new()  # in memory only: never written
	App.request_board("pachinko", "res://levels/pachinko/classic.board")


func after_each() -> void:
	App.save_data = _kept_save


func test_the_panel_keeps_its_place_when_a_best_appears() -> void:
	var game := await StretchedWindow.open(self, GAME, Vector2i(1280, 720), 4) as PachinkoGame
	var launcher_at := game.launcher.get_global_rect()
	var notes_at := game.notes.get_global_rect()
	App.save_data.record_pachinko_balls(game.rules.level.board_id, 12)
	game.restart()  # the board's notes again, now with a best
	await wait_process_frames(3)
	assert_string_contains(
		game.stats_panel.find_children("*", "RichTextLabel", true, false)[0].get_parsed_text(),
		"best +12"
	)
	assert_eq(game.notes.get_global_rect(), notes_at, "the notes stay where they were")
	assert_eq(game.launcher.get_global_rect(), launcher_at, "the launcher too")
	game.free()  # before its window


func test_the_cards_pocket_is_the_boards_colour() -> void:
	for board in ["classic", "windmills", "tulips", "fever", "hanami"]:
		var level := BoardLoader.load_board("res://levels/pachinko/%s.board" % board).level
		var icon := PieceIcon.new(level, BoardPieces.Piece.POCKET)
		var game_palette := FasciaBook.palette_of(level.fascia)
		assert_eq(icon.pocket_colour(), game_palette.petal, "%s: the card's pocket" % board)
		icon.free()
