class_name SettingsMenu
extends Control
## The settings screen, opened from the main menu and from the pause menu (it runs while the
## tree is paused). Changes apply at once; they are saved when the screen closes. Back, Esc
## or the gamepad's B closes it.

## The screen closed (it frees itself right after).
signal closed

## The designed widths (a landscape window), and the narrower ones a portrait window gets:
## there the screen is drawn bigger (its PortraitZoom) in fewer view units across.
const LABEL_WIDTH := 400.0
const SLIDER_WIDTH := 420.0
const SIDE_MARGIN := 56
const PORTRAIT_LABEL_WIDTH := 250.0
const PORTRAIT_SLIDER_WIDTH := 300.0
const PORTRAIT_SIDE_MARGIN := 12
const PORTRAIT_BUTTON_WIDTH := 190.0

@onready var _master: HSlider = %MasterSlider
@onready var _sfx: HSlider = %SfxSlider
@onready var _music: HSlider = %MusicSlider
@onready var _tilt: HSlider = %TiltSlider
@onready var _master_value: Label = %MasterValue
@onready var _sfx_value: Label = %SfxValue
@onready var _music_value: Label = %MusicValue
@onready var _tilt_value: Label = %TiltValue
@onready var _fullscreen: Button = %FullscreenCheck
@onready var _frame_counter: Button = %FrameCounterCheck
@onready var _ghost: Button = %GhostCheck
@onready var _maze_look: Button = %MazeLookCheck
@onready var _graphics: Button = %GraphicsCheck
@onready var _vibration: Button = %VibrationCheck
@onready var _screen_shake: Button = %ScreenShakeCheck
@onready var _unlock_all: Button = %UnlockAllCheck
@onready var _bindings: BindingList = %Bindings
@onready var _defaults: Button = %DefaultsButton
@onready var _back: Button = %BackButton
@onready var _backdrop: Control = $BackdropLayer/Backdrop
@onready var _margin: MarginContainer = $Margin
@onready var _first_label: Label = %MasterLabel


func _ready() -> void:
	process_mode = Node.PROCESS_MODE_ALWAYS
	_tilt.min_value = GameSettings.MIN_TILT_SENSITIVITY
	_tilt.max_value = GameSettings.MAX_TILT_SENSITIVITY
	_load_values()
	_master.value_changed.connect(_on_value_changed.bind("master_volume"))
	_sfx.value_changed.connect(_on_value_changed.bind("sfx_volume"))
	_music.value_changed.connect(_on_value_changed.bind("music_volume"))
	_tilt.value_changed.connect(_on_value_changed.bind("tilt_sensitivity"))
	_fullscreen.toggled.connect(_on_value_changed.bind("fullscreen"))
	_frame_counter.toggled.connect(_on_value_changed.bind("show_frame_counter"))
	_ghost.toggled.connect(_on_value_changed.bind("show_ghost"))
	_maze_look.toggled.connect(_on_value_changed.bind("maze_tutorial_look"))
	_graphics.toggled.connect(_on_value_changed.bind("maze_low_graphics"))
	_vibration.toggled.connect(_on_value_changed.bind("vibration"))
	_screen_shake.toggled.connect(_on_value_changed.bind("screen_shake"))
	_unlock_all.toggled.connect(_on_value_changed.bind("unlock_all_boards"))
	_defaults.pressed.connect(_on_defaults_pressed)
	_back.pressed.connect(close)
	App.settings.changed.connect(_load_values)
	var rows: Array[Control] = [
		_master,
		_sfx,
		_music,
		_tilt,
		_fullscreen,
		_frame_counter,
		_ghost,
		_maze_look,
		_graphics,
		_vibration,
		_screen_shake,
		_unlock_all
	]
	for control: Control in rows:
		_mark_row_on_focus(control)
	# on its own (not over a menu or a game) the screen brings its own background
	_backdrop.visible = get_parent() == get_tree().root
	get_viewport().size_changed.connect(_fit_to_window)
	_fit_to_window()
	_master.grab_focus.call_deferred()


func _unhandled_input(event: InputEvent) -> void:
	if _bindings.is_capturing():
		return
	if event.is_action_pressed("ui_cancel") or event.is_action_pressed("pause"):
		close()
		get_viewport().set_input_as_handled()
	elif event.is_action_pressed("ui_down") or event.is_action_pressed("ui_up"):
		if get_viewport().gui_get_focus_owner() == null:
			_master.grab_focus()  # focus lost to a mouse click: the keys take it back
			get_viewport().set_input_as_handled()


## Saves the settings and closes the screen.
func close() -> void:
	if is_queued_for_deletion():
		return
	App.save_settings()
	closed.emit()
	queue_free()


# A portrait window draws the screen bigger in less room: the rows get narrower to fit it.
func _fit_to_window() -> void:
	var view := get_viewport_rect().size
	var portrait := view.y > view.x
	_first_label.custom_minimum_size.x = PORTRAIT_LABEL_WIDTH if portrait else LABEL_WIDTH
	for slider: HSlider in [_master, _sfx, _music, _tilt]:
		slider.custom_minimum_size.x = PORTRAIT_SLIDER_WIDTH if portrait else SLIDER_WIDTH
	var side := PORTRAIT_SIDE_MARGIN if portrait else SIDE_MARGIN
	_margin.add_theme_constant_override("margin_left", side)
	_margin.add_theme_constant_override("margin_right", side)
	_bindings.set_button_width(PORTRAIT_BUTTON_WIDTH if portrait else BindingList.BUTTON_WIDTH)


func _load_values() -> void:
	var settings := App.settings
	_master.set_value_no_signal(settings.master_volume)
	_sfx.set_value_no_signal(settings.sfx_volume)
	_music.set_value_no_signal(settings.music_volume)
	_tilt.set_value_no_signal(settings.tilt_sensitivity)
	_fullscreen.set_pressed_no_signal(settings.fullscreen)
	_frame_counter.set_pressed_no_signal(settings.show_frame_counter)
	_ghost.set_pressed_no_signal(settings.show_ghost)
	_maze_look.set_pressed_no_signal(settings.maze_tutorial_look)
	_graphics.set_pressed_no_signal(settings.maze_low_graphics)
	_vibration.set_pressed_no_signal(settings.vibration)
	_screen_shake.set_pressed_no_signal(settings.screen_shake)
	_unlock_all.set_pressed_no_signal(settings.unlock_all_boards)
	_show_numbers()


func _on_value_changed(value: Variant, key: String) -> void:
	App.settings.set_value(key, value)
	App.settings.apply()


func _show_numbers() -> void:
	_fullscreen.text = "On" if _fullscreen.button_pressed else "Off"
	_frame_counter.text = "On" if _frame_counter.button_pressed else "Off"
	_ghost.text = "On" if _ghost.button_pressed else "Off"
	_maze_look.text = "Tutorial" if _maze_look.button_pressed else "Wood and steel"
	_graphics.text = "Low (faster)" if _graphics.button_pressed else "Full"
	_vibration.text = "On" if _vibration.button_pressed else "Off"
	_screen_shake.text = "On" if _screen_shake.button_pressed else "Off"
	_unlock_all.text = "On" if _unlock_all.button_pressed else "Off"
	_master_value.text = "%d%%" % roundi(_master.value * 100.0)
	_sfx_value.text = "%d%%" % roundi(_sfx.value * 100.0)
	_music_value.text = "%d%%" % roundi(_music.value * 100.0)
	_tilt_value.text = "×%.2f" % _tilt.value


## Sliders draw no focus ring, so the focused row's label gets a marker and a colour.
func _mark_row_on_focus(control: Control) -> void:
	var label := control.get_parent().get_child(control.get_index() - 1) as Label
	var plain := label.text
	control.focus_entered.connect(
		func() -> void:
			label.text = "▸ " + plain
			label.theme_type_variation = &"HeaderLabel"
			label.add_theme_font_size_override("font_size", 24)
	)
	control.focus_exited.connect(
		func() -> void:
			label.text = plain
			label.theme_type_variation = &""
	)


func _on_defaults_pressed() -> void:
	App.settings.restore_default_bindings()
	App.settings.apply()
	_bindings.rebuild()
	_defaults.grab_focus()
