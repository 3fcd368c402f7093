class_name PauseMenu
extends CanvasLayer
## The pause menu each game instances. The `pause` action (Esc / Start) opens it and pauses
## the whole tree, so the game's simulation stops; it runs itself while paused.
## Resume, Restart (emits `restart_requested`), Settings, Other boards (the game's level
## select) and Main menu (the title screen).

## The player chose Restart; the game resets its board (the tree is already unpaused).
signal restart_requested
## The menu opened (true) or closed (false).
signal pause_toggled(paused: bool)

const SETTINGS_SCENE := "res://scenes/menu/settings_menu.tscn"

var _settings: Control = null

@onready var _dim: Control = $Dim
@onready var _resume: Button = %ResumeButton
@onready var _restart: Button = %RestartButton
@onready var _settings_button: Button = %SettingsButton
@onready var _menu: Button = %MenuButton
@onready var _main_menu: Button = %MainMenuButton
@onready var _hint: Label = %Hint


func _ready() -> void:
	process_mode = Node.PROCESS_MODE_ALWAYS
	_dim.hide()
	_resume.pressed.connect(close)
	_restart.pressed.connect(_on_restart_pressed)
	_settings_button.pressed.connect(_open_settings)
	_menu.pressed.connect(_on_menu_pressed)
	_main_menu.pressed.connect(_on_main_menu_pressed)


func _unhandled_input(event: InputEvent) -> void:
	if _settings != null:
		return  # the settings screen handles its own way back
	if event.is_action_pressed("pause"):
		if is_open():
			close()
		else:
			open()
		get_viewport().set_input_as_handled()
	elif is_open() and event.is_action_pressed("ui_cancel"):
		close()
		get_viewport().set_input_as_handled()
	elif is_open() and (event.is_action_pressed("ui_down") or event.is_action_pressed("ui_up")):
		if get_viewport().gui_get_focus_owner() == null:
			_resume.grab_focus()  # focus lost to a mouse click: the keys take it back
			get_viewport().set_input_as_handled()


## True while the menu shows (and the tree is paused).
func is_open() -> bool:
	return _dim.visible


## Shows the menu and pauses the tree.
func open() -> void:
	if is_open():
		return
	get_tree().paused = true
	_hint.text = "%s: resume" % _pause_keys()
	_dim.show()
	_resume.grab_focus()
	pause_toggled.emit(true)


## Hides the menu and lets the game run again.
func close() -> void:
	if not is_open():
		return
	_close_settings()
	_dim.hide()
	get_tree().paused = false
	pause_toggled.emit(false)


## The current bindings of the pause action, as the player would name them.
func _pause_keys() -> String:
	var names := PackedStringArray()
	for event in App.settings.events_for("pause"):
		names.append(InputEventCodec.describe(event))
	return " / ".join(names) if not names.is_empty() else "Pause"


func _on_restart_pressed() -> void:
	close()
	restart_requested.emit()


# Back to the list of the game's boards, not the title screen: both play trials wanted to
# switch boards and went through three screens to do it.
func _on_menu_pressed() -> void:
	App.go_to_level_select(App.level_select_kind)


# A play trial found no way back to the title from a game but quitting it.
func _on_main_menu_pressed() -> void:
	App.go_to_menu()


## The settings screen opened from this menu (null while it is not open).
func open_settings_screen() -> Control:
	return _settings


func _open_settings() -> void:
	if not ResourceLoader.exists(SETTINGS_SCENE):
		return
	var scene: PackedScene = load(SETTINGS_SCENE)
	_settings = scene.instantiate() as Control
	_settings.tree_exited.connect(_on_settings_closed)
	add_child(_settings)


func _close_settings() -> void:
	if _settings != null:
		_settings.queue_free()


func _on_settings_closed() -> void:
	_settings = null
	if is_inside_tree() and is_open():
		_settings_button.grab_focus()
