class_name PachinkoGame
extends Control
## The pachinko game screen: loads the board the App picked, owns the PachinkoRules, draws
## the board on the left and the cup, launcher and stats on the right, and turns input
## actions, mouse and touch into calls on the rules. Sounds and effects follow its signals.

## The panel's designed width (PachinkoHudLayout).
const HUD_WIDTH := PachinkoHudLayout.HUD_WIDTH
## The board's area's short side in the designed 1280 × 720 layout: a full-power drag is 100
## view units there and as much longer as the board is bigger elsewhere (PachinkoInput).
const DESIGN_BOARD_SIDE := 720.0 - 2.0 * PachinkoHudLayout.MARGIN

var rules: PachinkoRules

var _level: BoardLevel
var _controls := PachinkoInput.new()
# Made once a board has loaded: a game with no board never owns one outside the tree.
var _bonus_view: BonusView
var _juice: JuiceView
var _gold_view: GoldPinsView
var _music: PachinkoMusic
var _recorder: ReplayRecorder
# The one-line reminder of how to shoot on games after the first (the full card's stand-in).
var _reminder := RulesReminder.new()
# R's question before it throws away a session with something in it.
var _restart_prompt := RestartPrompt.new()
# The board's part of the screen (the last layout's).
var _board_area := Rect2()
# This game's result (balls held less balls started): what its best counts.
var _record: PachinkoGameRecord
# The machine's goal this game, and the win moment's card.
var _goal: MachineGoal
var _cleared_card := MachineClearedCard.new()
# What the player sees and hears as the rules report (made once the views are ready).
var _feedback: PachinkoFeedback
# The side panel's numbers and notes line.
var _panel_feed: PachinkoPanelFeed

@onready var board_view: BoardView = $BoardView
@onready var hud: Control = $Hud
@onready var hud_column: BoxContainer = $Hud/Column
@onready var hud_info: BoxContainer = $Hud/Column/Info
@onready var cup: CupDisplay = $Hud/Column/Info/Readout/Cup
@onready var launcher: LauncherPanel = $Hud/Column/Launcher
@onready var stats_panel: StatsPanel = $Hud/Column/Info/Numbers/Stats
@onready var title: Label = $Hud/Column/Info/Readout/Title
@onready var notes: Label = $Hud/Column/Info/Numbers/Notes
@onready var instructions: InstructionsPanel = $Instructions
@onready var sounds: SoundBank = $Sounds
@onready var pause_menu: PauseMenu = $PauseMenu
@onready var _hud_layout := PachinkoHudLayout.new(hud, hud_column, hud_info, launcher)


func _ready() -> void:
	pause_menu.restart_requested.connect(restart)
	instructions.play_requested.connect(_start_from_card)
	_reminder.name = "Reminder"
	add_child(_reminder)
	move_child(_reminder, instructions.get_index() + 1)  # under the pause menu
	_restart_prompt.name = "RestartPrompt"
	add_child(_restart_prompt)  # last: its Esc is read before the pause menu's
	add_child(_cleared_card)
	move_child(_cleared_card, pause_menu.get_index())  # under the pause menu
	_cleared_card.next_requested.connect(_go_to_next_machine)
	_cleared_card.menu_requested.connect(App.go_to_level_select.bind(BoardLevel.PACHINKO_NAME))
	var path := App.current_board_path(BoardLevel.PACHINKO_NAME)
	var loaded := BoardLoader.load_board(path)
	if loaded.level == null or not loaded.level.is_pachinko():
		var problem := loaded.error if loaded.level == null else "%s is not a pachinko board" % path
		push_error("Pachinko: %s" % problem)
		title.text = "No board"
		instructions.show_problem(problem)
		return
	_level = loaded.level
	MachineDress.apply(self, _level, stats_panel, title, notes)
	SoundBank.warm(SoundBank.PACHINKO_FIRST_SOUNDS)
	_feedback = PachinkoFeedback.new(board_view, launcher, cup, sounds)
	_panel_feed = PachinkoPanelFeed.new(stats_panel, notes, _level, cup)
	_bonus_view = BonusView.new()
	add_child(_bonus_view)
	_bonus_view.attach(board_view, sounds)
	_juice = JuiceView.new()
	_juice.name = "Juice"
	add_child(_juice)
	_juice.attach(board_view, sounds)
	_gold_view = GoldPinsView.new()
	add_child(_gold_view)
	_gold_view.attach(board_view, sounds, _bonus_view)
	_music = PachinkoMusic.new()
	_music.name = "Music"
	add_child(_music)
	_music.play_machine(_level.fascia)
	launcher.flipper_pressed.connect(_on_flipper_pressed)
	launcher.handle_pressed.connect(_on_handle_pressed)
	launcher.handle_turned.connect(
		func(notches: float) -> void: _controls.turn_handle(rules, notches)
	)
	get_viewport().size_changed.connect(_layout)
	# the numbers wrap to the width they are given, so the panel's needs settle only once it
	# has been laid out in its band: fit it again when they change
	hud_column.minimum_size_changed.connect(_refit_portrait_hud, CONNECT_DEFERRED)
	_new_rules()
	_layout()


func _process(delta: float) -> void:
	# the cleared card holds the game still: no shot fires and no ball lands behind it
	if rules == null or _cleared_card.visible:
		return
	_controls.poll(rules, delta)
	# Slow motion slows the game's clock only: the same fixed steps, fewer per frame.
	rules.advance(delta * _juice.time_scale(rules, delta) * _bonus_view.time_scale(delta))
	_recorder.note_frame()
	_restart_prompt.follow(rules.balls_to_shoot)  # balls still landing change what R throws
	var aim := board_view.aim_preview()
	aim.held_back = _bonus_view.holds_the_aim(aim.aimed_power() >= 0.0)
	launcher.set_blocked(rules.loaded and rules.rail_blocked())
	_panel_feed.tick(delta)


func _notification(what: int) -> void:
	if what == NOTIFICATION_PAUSED and rules != null:
		_controls.let_go(rules)
		_restart_prompt.dismiss()


func _input(event: InputEvent) -> void:
	if rules != null and not _cleared_card.visible and _controls.handle_pointer(rules, event, self):
		get_viewport().set_input_as_handled()


func _unhandled_input(event: InputEvent) -> void:
	if rules == null:
		return
	if event.is_action_pressed("game_restart") and _cleared_card.visible:
		get_viewport().set_input_as_handled()  # the win card's own buttons decide (trial 5)
		return
	if event.is_action_pressed("game_restart"):
		# the same as the pause menu's Restart and as leaving for other boards: the session
		# so far counts for the board's best (R used to drop it); a session with something
		# in it asks first, and a second R starts over
		if rules.state == PachinkoRules.State.PLAYING and not _restart_prompt.asking():
			var stats := rules.stats(true)
			if RestartPrompt.wants_asking(stats, _level.cup_start_balls):
				# the question names the tray's count, settled (trial 8: the prompt said 80
				# and the tray 79 with a ball in flight)
				cup.catch_up(rules.balls_to_shoot)
				_restart_prompt.ask(RestartPrompt.balls_at_stake(stats))
				_restart_prompt.place(_board_area, _under_name_plate())
				get_viewport().set_input_as_handled()
				return
		restart()
		get_viewport().set_input_as_handled()
		return
	if rules.state != PachinkoRules.State.PLAYING:
		if instructions.ignores_held(event):
			get_viewport().set_input_as_handled()
		elif InstructionsPanel.is_click(event):
			# the card goes only by its own button (or a key): point the player at it
			instructions.nudge()
		elif InstructionsPanel.is_start_key(event) and instructions.accepts_start():
			_start_from_card()
			get_viewport().set_input_as_handled()
			# a held charge or handle key goes on to charge or stream: the player pressed it
			# to shoot, not only to close the instructions
			if event is InputEventKey and not event.is_action_pressed("game_start"):
				_controls.handle_action(rules, event)
		return
	if not _cleared_card.visible and _controls.handle_action(rules, event):
		get_viewport().set_input_as_handled()


## How far (view units) the flipper's grip is dragged up for full power in this layout.
## The bonus layer's views (reels, reach stage, jackpot banner), for tests and the
## screenshots.
func bonus_view() -> BonusView:
	return _bonus_view


## The screen's view effects (slow motion on the last balls, shakes, flashes).
func juice() -> JuiceView:
	return _juice


## The gold pins' view (the studs, their bursts, the prize's announcement).
func gold_view() -> GoldPinsView:
	return _gold_view


## What records this game for its replay.
func recorder() -> ReplayRecorder:
	return _recorder


## Places the board and the side panel for the window as it is now (the screen does it on
## every window change).
func lay_out() -> void:
	_layout()


func full_power_drag() -> float:
	return LaunchPower.MAX_POWER * _controls.drag_scale


## Starts over on the same board: a fresh world, the instructions up.
func restart() -> void:
	_keep_session()
	_new_rules()


## R's question before it starts over (for tests).
func restart_prompt() -> RestartPrompt:
	return _restart_prompt


func _exit_tree() -> void:
	_keep_session()


func _keep_session() -> void:
	_restart_prompt.dismiss()
	if _record != null:
		_record.keep_left_game()


func _new_rules() -> void:
	var rng_seed := int(Time.get_ticks_usec())
	rules = PachinkoRules.new(_level, rng_seed)
	rules.handle.set_power(App.pachinko_handle_power())  # as the player left it
	_record = PachinkoGameRecord.new(_level, rules)
	_goal = MachineGoal.new(_level, rules)
	_goal.reached.connect(_on_goal_reached)
	_panel_feed.bind(rules, _goal)
	_cleared_card.dismiss()
	_recorder = ReplayRecorder.new()
	_recorder.attach_pachinko(rules, rng_seed)
	rules.state_changed.connect(_on_state_changed)
	rules.game_ended.connect(_on_game_ended)
	board_view.bind(rules)
	_feedback.bind(rules)
	_bonus_view.bind(rules)
	_juice.bind(rules)
	_gold_view.bind(rules)
	_music.bind(rules)
	title.text = _level.display_name
	title.tooltip_text = _level.description
	launcher.show_controls_hint()
	_panel_feed.show_notes()
	if App.skips_rules_card(_level.board_id):
		# played from its full card before: straight into play, how to shoot in one line
		instructions.visible = false
		rules.start_game()
		_reminder.show_line(_reminder_line())
		_reminder.place(_board_area, _under_name_plate())
	else:
		_reminder.dismiss()
		instructions.show_start(_level)


## What each band of launch strengths has paid this game (lit on the launcher's bar).
func paying_strengths() -> PayingStrengths:
	return _feedback.paying


## The one-line reminder shown instead of the card on later games.
func reminder() -> RulesReminder:
	return _reminder


func _reminder_line() -> String:
	return (
		"%s\n%s   [b]%s[/b]: new game"
		% [
			InstructionsPanel.how_to_shoot_once(),
			InstructionsPanel.how_to_stream(),
			PlainMarkup.escape(KeyNames.of(&"game_restart", "?")),
		]
	)


## The board's part of the screen (the last layout's).
func board_area() -> Rect2:
	return _board_area


## The screen rectangle of the board's name plate at its widest.
func name_plate_rect() -> Rect2:
	var plate := NamePlate.rect_of(_level, NamePlate.MAX_WIDTH)
	var at := board_view.to_screen(plate.position)
	return Rect2(at, board_view.to_screen(plate.end) - at)


# The screen height just under the board's name plate.
func _under_name_plate() -> float:
	return name_plate_rect().end.y + 6.0


func _layout() -> void:
	if _level == null or not is_inside_tree():  # a window closing around it resizes too
		return
	var area := _hud_layout.place(get_viewport_rect().size)
	_board_area = area
	board_view.fit(_level, area)
	_reminder.place(area, _under_name_plate())
	_controls.drag_scale = minf(area.size.x, area.size.y) / DESIGN_BOARD_SIDE
	instructions.position = area.position
	instructions.size = area.size


func _refit_portrait_hud() -> void:
	if _level != null:
		_hud_layout.refit(get_viewport_rect().size)


# The player chose to play from the card (its button or a start key).
func _start_from_card() -> void:
	if rules == null or rules.state == PachinkoRules.State.PLAYING:
		return
	rules.start_game()
	App.note_pachinko_rules_seen(_level.board_id)
	sounds.play(SoundBank.UI_CLICK)


# The launcher is a deliberate control of its own: grabbing it while the card is up starts
# the game, once the card has been up long enough that the press is not a stray one.
func _on_flipper_pressed(at: Vector2) -> void:
	if _cleared_card.visible:
		return
	if rules.state != PachinkoRules.State.PLAYING:
		if instructions.accepts_start():
			_start_from_card()
		else:
			instructions.nudge()
		return
	_controls.begin_drag(rules, at)


func _on_handle_pressed(at: Vector2) -> void:
	if _cleared_card.visible:
		return
	if rules.state != PachinkoRules.State.PLAYING:
		if not instructions.accepts_start():
			instructions.nudge()
			return
		_start_from_card()
	_controls.begin_handle_drag(rules, at)


func _on_state_changed(state: PachinkoRules.State) -> void:
	if state == PachinkoRules.State.PLAYING:
		instructions.visible = false
	launcher.set_loaded(rules.loaded)


func _on_game_ended(summary: Dictionary) -> void:
	summary["game_won"] = _record.result()
	var new_best := _record.finish()
	ReplayStore.save(_recorder.finish(), ReplayStore.last_pachinko_path(_level.board_id))
	var best := App.best_pachinko_balls(_level.board_id)
	_reminder.dismiss()
	instructions.show_game_over(_level, summary, best, new_best)
	_panel_feed.show_notes()
	sounds.play(SoundBank.GAME_OVER)


## The win moment's card (the tray reached the machine's goal).
func cleared_card() -> MachineClearedCard:
	return _cleared_card


func _on_goal_reached(_won: int) -> void:
	_controls.let_go(rules)  # a held key or drag fires nothing behind the card
	# the tray first, the panel from it, the card from the same balls: trial 8's panel read
	# "Up 1" beside a card's "You won 11" (the clearing pocket's 10 still pouring)
	cup.catch_up(rules.balls_to_shoot)
	_record.keep_clear()  # the best counts at once, not when the game is left
	_panel_feed.mark_cleared()
	_restart_prompt.dismiss()  # no "New game?" over the card
	_bonus_view.banner.dismiss()  # nor a jackpot's summary card under it
	_cleared_card.show_cleared(_level, _record.result(), _board_area, _goal.jackpot_paid())
	sounds.play(SoundBank.JACKPOT_FANFARE)


func _go_to_next_machine() -> void:
	App.start_game(BoardLevel.PACHINKO_NAME, MachineGoal.next_board_path(_level))
