extends Control
## The level select of one game (App.level_select_kind): every board file in levels/<kind>/
## as a card with its thumbnail, name and best result; boards that fail to load are listed
## greyed out with their error. Choosing a card starts the game on that board.

const LevelCard := preload("res://scenes/menu/level_card.gd")
const MazeCardProgress := preload("res://scenes/menu/maze_card_progress.gd")
const TITLES := {"pachinko": "Pachinko", "maze": "Tilt Maze"}

## The game whose boards are listed ("pachinko" or "maze").
var kind := "pachinko"

@onready var _title: Label = %TitleLabel
@onready var _summary: Label = %SummaryLabel
@onready var _grid: GridContainer = %Cards
@onready var _back: Button = %BackButton


func _ready() -> void:
	_back.pressed.connect(App.go_to_menu)
	kind = App.level_select_kind
	show_boards(BoardLoader.list_boards(_kind_enum(kind)))


func _unhandled_input(event: InputEvent) -> void:
	if event.is_action_pressed("ui_cancel"):
		App.go_to_menu()
		get_viewport().set_input_as_handled()
	elif _is_navigation(event) and get_viewport().gui_get_focus_owner() == null:
		# a mouse click on empty space drops focus: the keys and the pad take it back
		var first := first_card()
		(first if first != null else _back).grab_focus()
		get_viewport().set_input_as_handled()


## Lists these load results as cards (one per file, broken ones greyed) and focuses the first.
func show_boards(results: Array[BoardLoadResult]) -> void:
	for child in _grid.get_children():
		_grid.remove_child(child)
		child.queue_free()
	_title.text = "%s: choose a board" % TITLES.get(kind, kind.capitalize())
	var broken := 0
	if kind == "maze":
		results = MazeProgress.sorted(results)
	for result in results:
		var card := LevelCard.new()
		card.setup(result, _best_text(result))
		if card.playable:
			card.pressed.connect(App.start_game.bind(kind, card.board_path))
		else:
			broken += 1
		_grid.add_child(card)
	if kind == "maze":
		MazeCardProgress.apply(cards())
	_summary.text = _summary_text(results.size(), broken)
	var first := first_card()
	if first != null:
		first.grab_focus()
	else:
		_back.grab_focus()


## The cards shown, in order.
func cards() -> Array[Button]:
	var result: Array[Button] = []
	for child in _grid.get_children():
		if child is Button and not child.is_queued_for_deletion():
			result.append(child as Button)
	return result


## The first playable card, else the first card, else null.
func first_card() -> Button:
	var all := cards()
	for card in all:
		if not card.disabled:
			return card
	return all[0] if not all.is_empty() else null


func _best_text(result: BoardLoadResult) -> String:
	if not result.ok():
		return ""
	var board_id := result.level.board_id
	if kind == "maze":
		var seconds := App.best_maze_time(board_id)
		if seconds <= 0.0:
			return ""
		# the same m:ss.t the maze's own clock shows
		var minutes := floori(seconds / 60.0)
		var whole := int(seconds)
		return "Best time: %d:%02d.%d" % [minutes, whole % 60, int(fmod(seconds, 1.0) * 10.0)]
	var balls := App.best_pachinko_balls(board_id)
	return "Best: %d balls won" % balls if balls >= 0 else ""


func _summary_text(total: int, broken: int) -> String:
	if total == 0:
		return "No boards found in levels/%s/." % kind
	var text := "%d board%s" % [total, "" if total == 1 else "s"]
	if broken > 0:
		text += ", %d could not be loaded (shown greyed, with the reason)" % broken
	return text


static func _is_navigation(event: InputEvent) -> bool:
	for action: String in ["ui_up", "ui_down", "ui_left", "ui_right"]:
		if event.is_action_pressed(action):
			return true
	return false


static func _kind_enum(kind_name: String) -> int:
	return BoardLevel.Kind.MAZE if kind_name == "maze" else BoardLevel.Kind.PACHINKO
