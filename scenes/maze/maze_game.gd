class_name MazeGame
extends Control
## The tilt maze screen: loads the board the App picked, owns the MazeRules, feeds it the
## tilt from the joystick / keys / stick / accelerometer, and shows the result: the board in
## 3D with raised walls and rolling balls (maze_stage.gd), their sounds and rumble, and the
## seed's note, with a timer, the best time and the mode beside the joystick.

## After a window change the panel is placed again this many frames running, while its
## wrapped text settles to the new width.
const SETTLE_FRAMES := 3
## Wall hits quieter than this (px/s) make no sound.
const THUD_MIN_SPEED := 20.0

## The rules of the board being played (null if no board could be loaded).
var rules: MazeRules
## Where the tilt comes from.
var mixer := TiltMixer.new()
## Gamepad rumble and phone buzz on knocks and drops.
var haptics := MazeHaptics.new()

var _sounds: SoundBank
var _goal_count := 0
var _lines: MazeSideLines
var _recorder := ReplayRecorder.new()
var _ghost: GhostRun
var _ghost_view := MazeGhost3d.new()
var _rolling: MazeBallSounds
var _win_panel := MazeWinPanel.new()
## A mouse drag on the board itself tilts it, as the joystick does.
var _drag := MazeBoardDrag.new()
var _panel_layout: MazePanelLayout
## Frames left in which the panel is placed again after a window change (SETTLE_FRAMES).
var _settle_frames := 0
## True from a ball lost until the card saying so is up (it waits for the ball to drop).
var _loss_card_due := false

@onready var _stage: MazeStage = $Stage
@onready var _side: VBoxContainer = $Side
@onready var _joystick: MazeJoystick = %Joystick
@onready var _note: MazeNote = %Note
@onready var _title: Label = %Title
@onready var _mode: Label = %Mode
@onready var _timer: Label = %Timer
@onready var _best: Label = %Best
@onready var _next_medal: Label = %NextMedal
@onready var _in_goal: Label = %InGoal
@onready var _calibrate: Button = %Calibrate
@onready var _controls: Label = %Controls


func _ready() -> void:
	_lines = MazeSideLines.new(_mode, _timer, _best, _next_medal, _in_goal)
	_sounds = SoundBank.new()
	add_child(_sounds)
	SoundBank.warm([SoundRecipes.BALL_ROLL, SoundRecipes.BALL_DROP, SoundBank.WALL_THUD])
	_rolling = MazeBallSounds.new()
	add_child(_rolling)
	haptics.enabled = App.settings.vibration
	App.settings.changed.connect(_on_settings_changed)
	add_child(_win_panel)
	_win_panel.next_board_chosen.connect(_on_next_board)
	_win_panel.retry_chosen.connect(_on_retry)
	_win_panel.menu_chosen.connect(App.go_to_level_select.bind(BoardLevel.MAZE_NAME))
	var pause_menu := MazeGameSetup.add_scene(self, MazeGameSetup.PAUSE_MENU) as PauseMenu
	if pause_menu != null:
		pause_menu.restart_requested.connect(_on_retry)
	MazeGameSetup.add_scene(self, MazeGameSetup.FRAME_COUNTER)
	mixer.sensitivity = App.settings.tilt_sensitivity
	_joystick.sensitivity = App.settings.tilt_sensitivity
	_drag.sensitivity = App.settings.tilt_sensitivity
	_joystick.pressed.connect(_on_joystick_pressed)
	_joystick.moved.connect(mixer.joystick_moved)
	add_child(_drag)
	_drag.pressed.connect(_start)
	_drag.moved.connect(_on_board_dragged)
	_calibrate.pressed.connect(_on_calibrate)
	MazeFocusRing.apply(_calibrate)
	_calibrate.visible = false
	_controls.text = MazeHints.controls()
	var loaded := MazeGameSetup.load_level()
	var level: BoardLevel = loaded.level
	if level == null:
		_note.show_note("This board could not be loaded.", loaded.problem)
		_joystick.hide()
		return
	# the mode the player last chose, however they came here, where the board has black holes
	var hard_asked := App.maze_hard_chosen
	rules = MazeRules.new(level, hard_asked and not level.holes.is_empty())
	_recorder.attach_maze(rules)
	_stage.add_on_board(_ghost_view)
	_ghost_view.set_board_size(level.size)
	rules.won.connect(_on_won)
	rules.lost.connect(_on_lost)
	rules.game_reset.connect(_on_game_reset)
	rules.goal_count_changed.connect(_on_goal_count_changed)
	rules.wall_bumped.connect(_on_wall_bumped)
	_stage.tutorial_look = App.settings.maze_tutorial_look
	_stage.set_level(level, rules.hard_mode)
	_stage.set_look(App.settings.maze_low_graphics, App.settings.maze_tutorial_look)
	get_viewport().size_changed.connect(_on_size_changed)
	_layout()
	_settle_frames = SETTLE_FRAMES  # placed again as the panel's text settles, then kept
	_title.text = level.display_name if not level.display_name.is_empty() else level.board_id
	_on_game_reset()
	if hard_asked and not rules.hard_mode:
		_note.show_note(MazeHints.tilt_to_start(), MazeHints.easy_here())
	# the first frame drawn shows the board ready: its balls and the medal in reach
	_stage.sync_balls(rules, 0.0)
	_lines.show_next_medal(rules)
	# with a window, the curtain stays up (its ring turning) while the board's parts come on
	# one frame at a time, each compiling its shaders (headless nothing is drawn)
	if DisplayServer.get_name() != "headless":
		var step_in := MazeStepIn.new()
		add_child(step_in)
		App.curtain.hold_until(step_in.shown_in_full, self)
		step_in.start(_stage)


func _process(delta: float) -> void:
	if _settle_frames > 0:
		_settle_frames -= 1
		_layout()
	if rules == null:
		return
	var keys := Input.get_vector("tilt_left", "tilt_right", "tilt_up", "tilt_down")
	var accel := Input.get_accelerometer()
	mixer.observe(accel)
	_calibrate.visible = mixer.has_accelerometer()
	if rules.state == MazeRules.State.READY and keys != Vector2.ZERO:
		_start()
	MazeFrameSteps.play_frame(rules, _recorder, delta, mixer, keys, accel)
	_joystick.fine = not rules.is_over() and Input.is_action_pressed("tilt_fine")
	# the head shows the keys' tilt, and once the run is over the board levelling (trial 9:
	# it stayed off-centre behind the result card)
	if mixer.source != TiltMixer.Source.JOYSTICK or rules.is_over():
		_joystick.head_offset = TiltInput.joystick_from_tilt(rules.tilt)
	if _ghost != null and not rules.is_over():  # it stops at the finish, as the clock does
		_ghost.sync(rules.world.step_count)
		_ghost_view.show_balls(_ghost.positions(), _ghost.ball_radius())
	_stage.set_tilt(rules.tilt)
	_stage.sync_balls(rules, delta)
	if rules.is_playing():
		_rolling.update(rules.world.get_velocities(), delta)
	else:
		_rolling.stop_all()
	_lines.show_clock(rules)
	if rules.state == MazeRules.State.LOST:
		# two balls may drop at once; the rules end the run at the first
		_lines.show_balls_left(rules.balls_left(), rules.ball_total(), false)
	_lines.step_flash(delta)
	if _loss_card_due and _stage.balls().fall_progress() >= 1.0:
		_loss_card_due = false
		_win_panel.present_loss()


func _unhandled_input(event: InputEvent) -> void:
	if rules == null:
		return
	var pressed := KeyTilt.pressed_direction(event)
	if pressed != Vector2.ZERO and (rules.is_playing() or rules.state == MazeRules.State.READY):
		# the press itself nudges the board, however soon the key comes up (trial 9)
		_start()
		mixer.key_pressed(pressed)
	if event.is_action_pressed("maze_reset") or event.is_action_pressed("game_restart"):
		rules.reset()
	elif event.is_action_pressed("maze_hard_mode"):
		_choose_hard_mode()
	elif event.is_action_pressed("maze_easy_mode"):
		rules.set_hard_mode(false)
		App.maze_hard_chosen = false
	elif event.is_action_pressed("maze_calibrate"):
		_on_calibrate()
	elif event.is_action_pressed("game_start") and rules.state == MazeRules.State.READY:
		_start()
	else:
		return
	get_viewport().set_input_as_handled()


## The screen's sound bank (its players and the sounds they hold).
func sounds() -> SoundBank:
	return _sounds


## The best run's ghost being replayed, or null (none recorded, or the setting is off).
func ghost() -> GhostRun:
	return _ghost


## The ghost's 3D view (hidden while there is no ghost).
func ghost_view() -> Node3D:
	return _ghost_view


## Places the side panel and frames the board for the window as it is now (the screen does it
## on every window change); returns the board's region in screen pixels.
func lay_out() -> Rect2:
	return _layout()


## The 3D stage showing the board (for tests and the screenshots).
func stage() -> MazeStage:
	return _stage


# A board without black holes has no hard mode (trial 8: H on First Roll started a second
# best time, "--", for the same game): H says so before the first tilt and changes nothing.
func _choose_hard_mode() -> void:
	if not rules.level.holes.is_empty():
		rules.set_hard_mode(true)
		App.maze_hard_chosen = true
	elif rules.state == MazeRules.State.READY:
		_note.show_note(MazeHints.tilt_to_start(), MazeHints.no_hard_mode())


func _start() -> void:
	if rules == null or rules.state != MazeRules.State.READY:
		return
	rules.start()
	_note.fade_out()
	_sounds.play(SoundBank.UI_CLICK, -8.0)


func _on_joystick_pressed() -> void:
	if rules != null and rules.state == MazeRules.State.READY:
		_start()
	elif rules != null and rules.is_over():
		rules.reset()
		_start()


# A drag on the board tilts it as the joystick would, and shows the joystick's head there.
func _on_board_dragged(offset: Vector2) -> void:
	if rules != null and (rules.is_playing() or offset == Vector2.ZERO):
		mixer.joystick_moved(offset)
		_joystick.head_offset = offset


func _on_calibrate() -> void:
	# the joystick lets go, or the next pointer move would take the tilt straight back
	_joystick.engaged = false
	mixer.calibrate()
	_sounds.play(SoundBank.UI_CLICK, -8.0)


func _on_game_reset() -> void:
	_loss_card_due = false
	_goal_count = 0
	_lines.show_attempt(rules.hard_mode, rules.ball_total())
	_win_panel.hide()
	_ghost = MazeGhost3d.best_run(rules.level, rules.hard_mode)
	_ghost_view.set_board_size(rules.level.size)
	_ghost_view.clear()
	_joystick.release()
	_drag.release()
	mixer.reset()
	_stage.set_tilt(Vector2.ZERO)
	_stage.set_hard_mode(rules.hard_mode)
	var hint := MazeHints.start(
		rules.hard_mode, rules.ball_total(), rules.level.holes.size(), rules.level.board_id
	)
	hint += MazeHints.ghost_line(_ghost != null, App.settings.show_ghost)
	_note.show_note(MazeHints.tilt_to_start(), hint)
	_show_best()


func _on_won(seconds: float) -> void:
	_joystick.release()
	_drag.release()
	var board_id := rules.level.board_id
	var before := App.best_maze_time(board_id, rules.hard_mode)
	var summary := MazeWinSummary.of(rules.level, rules.hard_mode, seconds, before)
	var best := App.record_maze_time(board_id, rules.hard_mode, seconds)
	if best:
		var path := ReplayStore.best_maze_path(board_id, rules.hard_mode)
		ReplayStore.save(_recorder.finish(), path)
	# the card says it was done; the panel only says what else there is to try
	_note.show_or_fade(MazeHints.won(rules.hard_mode, rules.level.holes.size()))
	_lines.show_medal_line(summary.medal_line())
	_show_best()
	var has_next := not MazeProgress.next_path(board_id).is_empty()
	_win_panel.present(summary, rules.hard_mode, has_next)
	_sounds.play(SoundBank.FANFARE)
	if summary.medal != Medals.Medal.NONE:
		# a chime on top, higher for a better medal
		_sounds.play(SoundBank.GOAL_CHIME, -4.0, 1.0 + 0.25 * float(summary.medal))


func _on_size_changed() -> void:
	if not is_inside_tree():  # a window closing around the screen resizes as it goes
		return
	if _panel_layout != null:
		_panel_layout.window_changed()
	_layout()
	# the panel's text wraps to the new width only as its container sorts, over the next
	# frames: place it again then, or a window grown back keeps the small window's joystick
	_settle_frames = SETTLE_FRAMES


## Puts the side panel where the window's shape leaves room (MazePanelLayout) and frames the
## board in the rest. Returns the board's region (screen pixels).
func _layout() -> Rect2:
	if _panel_layout == null:
		_panel_layout = MazePanelLayout.new(_side, _joystick)
		# the medal line says "Gold by 0:20.4" or a longer line that may wrap
		_panel_layout.reserve_lines(_next_medal, 2)
	var stretch := get_viewport().get_final_transform().get_scale().y
	_panel_layout.place_text(stretch)
	_lines.hold_time_widths()
	var aspect := _stage.framing().board_aspect if rules != null else 0.0
	var region := _panel_layout.place(get_viewport_rect().size, stretch, aspect)
	if _panel_layout.needs_retry and not get_tree().process_frame.is_connected(_layout):
		get_tree().process_frame.connect(_layout, CONNECT_ONE_SHOT)
	_stage.set_board_region(region)
	_drag.region = region
	_win_panel.set_anchors_preset(Control.PRESET_TOP_LEFT)
	_win_panel.position = region.position
	_win_panel.size = region.size
	return region


## The win panel (for tests and the screenshots).
func win_panel() -> MazeWinPanel:
	return _win_panel


func _on_next_board() -> void:
	var path := MazeProgress.next_path(rules.level.board_id)
	if not path.is_empty():
		App.start_game(BoardLevel.MAZE_NAME, path)


func _on_retry() -> void:
	if rules != null:
		rules.reset()


func _on_lost(hole: int) -> void:
	_joystick.release()
	_drag.release()
	_lines.show_medal_line("")
	_stage.set_lost_hole(hole)
	_sounds.play(SoundRecipes.BALL_DROP)
	haptics.drop()
	var lost := MazeHints.lost()
	# at once, not faded in: the run is over (every ball must reach the dip)
	_note.show_note_now(lost[0], lost[1])
	_sounds.play(SoundBank.HOLE_FALL, -9.0)
	_lines.show_balls_left(rules.balls_left(), rules.ball_total(), true)
	# the card with Retry comes up once the ball has dropped out of sight (_process)
	_loss_card_due = not rules.can_still_win()


## True while the panel's count flashes (for tests).
func count_flashing() -> bool:
	return _lines.count_flashing()


# The rules counted a ball in (or out): the panel's count at once, and for a ball in, a
# small chime (higher for each) and the goal's dish lit up.
func _on_goal_count_changed(count: int) -> void:
	if count > _goal_count:
		_sounds.play(SoundBank.GOAL_CHIME, -10.0, 0.9 + 0.1 * float(count))
		_stage.light_goal()
	_goal_count = count
	_lines.show_goal_count(count, rules.ball_total())


## The panel's "In goal 2 / 4" line (for tests).
func goal_count_text() -> String:
	return _lines.goal_count_text()


## The panel's medal line (for tests).
func next_medal_text() -> String:
	return _lines.medal_line()


func _on_wall_bumped(speed: float) -> void:
	_sounds.play_impact(SoundBank.WALL_THUD, speed, THUD_MIN_SPEED, 94.0)
	haptics.knock(speed)


func _on_settings_changed() -> void:
	haptics.enabled = App.settings.vibration
	mixer.sensitivity = App.settings.tilt_sensitivity
	_joystick.sensitivity = App.settings.tilt_sensitivity
	_drag.sensitivity = App.settings.tilt_sensitivity
	var low := App.settings.maze_low_graphics
	var tutorial := App.settings.maze_tutorial_look
	if _stage.low_graphics != low or _stage.tutorial_look != tutorial:
		_stage.set_look(low, tutorial)  # at once, on the board in play (trial 7)


func _show_best() -> void:
	_lines.show_best(rules.level.board_id, rules.hard_mode)
	if _panel_layout != null:
		_layout()  # a narrowed column widens again for a longer line (never while playing)
