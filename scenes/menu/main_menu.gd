class_name MainMenu
extends Control
## The title screen: Play Pachinko, Pachinko boards, Tilt Maze, Settings, Quit. Play
## Pachinko, the default, goes straight to a board (Classic for a new player, else the one
## last played): a play trial took 27 s from launch to a board through the list. The first
## button takes focus so keyboard and gamepad work at once; problems met while loading the
## player's files are shown once in a banner at the bottom.

const SETTINGS_SCENE := preload("res://scenes/menu/settings_menu.tscn")
## The board a new player's Play Pachinko starts.
const CLASSIC_PACHINKO := "res://levels/pachinko/classic.board"

var _settings: Control = null

@onready var _play: Button = %PlayButton
@onready var _pachinko: Button = %PachinkoButton
@onready var _maze: Button = %MazeButton
@onready var _settings_button: Button = %SettingsButton
@onready var _quit: Button = %QuitButton
@onready var _notice: Control = %Notice
@onready var _notice_label: Label = %NoticeLabel
@onready var _version: Label = %VersionLabel
@onready var _hint: Label = %Hint
@onready var _title_gap: Control = %Gap


func _ready() -> void:
	_play.pressed.connect(_play_pachinko)
	_pachinko.pressed.connect(App.go_to_level_select.bind(BoardLevel.PACHINKO_NAME))
	_maze.pressed.connect(App.go_to_level_select.bind(BoardLevel.MAZE_NAME))
	_settings_button.pressed.connect(_open_settings)
	_quit.pressed.connect(get_tree().quit)
	_version.text = "v%s" % ProjectSettings.get_setting("application/config/version", "")
	var problems := App.take_problems()
	_notice.visible = not problems.is_empty()
	_notice_label.text = "⚠ " + "\n⚠ ".join(problems)
	# a long banner would run into the hint line: the banner matters more, so it takes the room
	_hint.visible = problems.is_empty()
	if not problems.is_empty():
		_title_gap.custom_minimum_size.y = 16.0
	_focus_first()
	# Play Pachinko's scene loads while the player reads the title (after its first frame)
	if DisplayServer.get_name() != "headless":
		RenderingServer.frame_post_draw.connect(
			App.preload_game.bind(BoardLevel.PACHINKO_NAME), CONNECT_ONE_SHOT
		)


func _unhandled_input(event: InputEvent) -> void:
	if _settings == null and get_viewport().gui_get_focus_owner() == null:
		if event.is_action_pressed("ui_up") or event.is_action_pressed("ui_down"):
			_focus_first()
			get_viewport().set_input_as_handled()


func _focus_first() -> void:
	# coming back from the maze's level select, the maze keeps focus; else Play
	(_maze if App.level_select_kind == BoardLevel.MAZE_NAME else _play).grab_focus()


## The board Play Pachinko starts: the one last played this run, else Classic.
static func play_board_path() -> String:
	var last := App.last_board_path(BoardLevel.PACHINKO_NAME)
	return last if not last.is_empty() else CLASSIC_PACHINKO


func _play_pachinko() -> void:
	App.start_game(BoardLevel.PACHINKO_NAME, play_board_path())


func _open_settings() -> void:
	_settings = SETTINGS_SCENE.instantiate() as Control
	_settings.tree_exited.connect(_on_settings_closed)
	add_child(_settings)


func _on_settings_closed() -> void:
	_settings = null
	if is_inside_tree():
		_settings_button.grab_focus()
