@tool
extends Button
## The board tool's "Generate maze…" button and its dialog: columns, rows, black holes,
## difficulty and seed; Generate replaces the edited maze's layout in one undo step
## (GenerateMazeAction). Shown only while a maze board is edited.

const GenerateMazeAction := preload("res://addons/board_editor/generator/generate_maze_action.gd")
const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")

var _session: BoardEditSession
var _dialog: ConfirmationDialog
var _cols: SpinBox
var _rows: SpinBox
var _holes: SpinBox
var _difficulty: HSlider
var _seed: SpinBox


func _init() -> void:
	text = "Generate maze…"
	tooltip_text = "Replace this maze with a new, solvable one made from a seed."
	pressed.connect(open_dialog)
	_dialog = ConfirmationDialog.new()
	_dialog.title = "Generate maze"
	_dialog.ok_button_text = "Generate"
	_dialog.get_ok_button().pressed.connect(_on_generate)
	var grid := GridContainer.new()
	grid.columns = 2
	_dialog.add_child(grid)
	_cols = _spin(grid, "Columns", MazeGenSettings.MIN_CELLS, MazeGenSettings.MAX_CELLS, 10)
	_rows = _spin(grid, "Rows", MazeGenSettings.MIN_CELLS, MazeGenSettings.MAX_CELLS, 9)
	_holes = _spin(grid, "Black holes", 0, 400, 6)
	_add_label(grid, "Difficulty")
	_difficulty = HSlider.new()
	_difficulty.max_value = 1.0
	_difficulty.step = 0.05
	_difficulty.value = 0.5
	_difficulty.custom_minimum_size = Vector2(160, 0)
	_difficulty.tooltip_text = "Easy: many loops, holes in dead ends. Hard: few loops."
	grid.add_child(_difficulty)
	_seed = _spin(grid, "Seed", 0, 999999, 1)
	add_child(_dialog)


## Edits the maze of `session` from now on (hidden for a pachinko board).
func bind(session: BoardEditSession) -> void:
	_session = session
	visible = session != null and session.level != null and session.level.is_maze()


## The settings the dialog shows, for the edited board.
func settings() -> MazeGenSettings:
	var values := {
		"cols": int(_cols.value),
		"rows": int(_rows.value),
		"holes": int(_holes.value),
		"difficulty": _difficulty.value,
		"seed": int(_seed.value),
	}
	if _session != null and _session.level != null:
		values["id"] = _session.level.board_id.trim_prefix("maze_")
		values["title"] = _session.level.display_name
	var chosen := MazeGenSettings.new()
	chosen.read(values)
	return chosen


## Opens the dialog with the edited board's grid size.
func open_dialog() -> void:
	if _session != null and _session.level != null:
		_cols.value = clampi(
			_session.level.grid_cols, MazeGenSettings.MIN_CELLS, MazeGenSettings.MAX_CELLS
		)
		_rows.value = clampi(
			_session.level.grid_rows, MazeGenSettings.MIN_CELLS, MazeGenSettings.MAX_CELLS
		)
	_dialog.popup_centered()


## Generates with the dialog's settings and commits the one undoable action; returns the
## problem ("" when the board was replaced).
func generate() -> String:
	if _session == null or _session.level == null:
		return "No board is being edited."
	if not _session.level.is_maze():
		return "The maze generator works on maze boards only."
	var made := MazeGenerator.generate(settings())
	if made.has("error"):
		return made["error"]
	var generated: BoardLevel = made["level"]
	_session.commit(GenerateMazeAction.new(_session.level, generated))
	return ""


func _on_generate() -> void:
	var problem := generate()
	if not problem.is_empty():
		push_warning("Generate maze: " + problem)


func _spin(grid: GridContainer, label: String, low: int, high: int, value: int) -> SpinBox:
	_add_label(grid, label)
	var spin := SpinBox.new()
	spin.min_value = low
	spin.max_value = high
	spin.value = value
	grid.add_child(spin)
	return spin


func _add_label(grid: GridContainer, words: String) -> void:
	var label := Label.new()
	label.text = words
	grid.add_child(label)
