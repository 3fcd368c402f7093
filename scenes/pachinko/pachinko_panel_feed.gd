class_name PachinkoPanelFeed
extends RefCounted
## Feeds the side panel's numbers (StatsPanel) and the notes line under it: one game's
## figures from its rules, its balls from the tray's own count (CupDisplay.shown_changed,
## in the same frame the tray changes: trial 8 saw the tray at 107 and the panel at 101),
## the rest refreshed a few times a second. PachinkoGame makes one and binds it to each game.

## Seconds between the panel's refreshes while nothing else refreshes it.
const REFRESH_SECONDS := 0.25

var _panel: StatsPanel
var _notes: Label
var _level: BoardLevel
var _rules: PachinkoRules
var _goal: MachineGoal
var _cup: CupDisplay
var _refresh := 0.0
# The tray's count the panel last showed: it follows the tray as its balls land.
var _shown_tray := -1


## Feeds `panel` and `notes` for games on `level`; the tray's count is the one `cup` shows.
func _init(panel: StatsPanel, notes: Label, level: BoardLevel, cup: CupDisplay) -> void:
	_panel = panel
	_notes = notes
	_level = level
	_cup = cup
	cup.shown_changed.connect(_on_tray_shown)


## Follows the game `rules` (a new one each game), whose goal `goal` watches.
func bind(rules: PachinkoRules, goal: MachineGoal) -> void:
	_rules = rules
	_goal = goal
	_panel.goal_cleared = false


## Counts `delta` seconds of play and refreshes the panel when its time has come.
func tick(delta: float) -> void:
	_refresh -= delta
	if _refresh <= 0.0 or _tray_count() != _shown_tray:
		_refresh = REFRESH_SECONDS
		show_now()


## Shows the game's figures now.
func show_now() -> void:
	_panel.goal_pending = _goal != null and _goal.is_waiting()
	var stats := panel_stats()
	_shown_tray = stats["balls_left"]
	_panel.show_stats(stats)
	GoldPinsText.show_under(_panel, _rules)  # the gold pins' line, a label of its own


## Marks the goal cleared on the panel, with the board's best as the clear left it.
func mark_cleared() -> void:
	_panel.goal_cleared = true
	_panel.best_session = App.best_pachinko_balls(_level.board_id)
	show_now()


## The board's best, its goal and the keys' line: shown at each game's start and end.
func show_notes() -> void:
	# the best is the stats' "Best session" line, whose place is kept from the start: a line
	# of its own here appeared after the first game and moved the panel under it
	_panel.best_session = App.best_pachinko_balls(_level.board_id)
	_panel.goal = PachinkoGoals.tray_target(_level)
	show_now()
	_notes.text = (
		"%s new game  ·  %s pause  ·  %s frame counter"
		% [
			KeyNames.of(&"game_restart", "?"),
			KeyNames.of(&"pause", "?"),
			KeyNames.of(&"toggle_frame_counter", "?"),
		]
	)


## The panel's numbers: the rules' this game, the balls the tray's.
func panel_stats() -> Dictionary:
	var stats := _rules.stats(true)
	stats["start_balls"] = _level.cup_start_balls  # the panel's "Won this game +45"
	# the tray's number, not the rules' count ahead of the balls still pouring in (trial 7
	# read 22 on the tray and "25 now" on the panel); behind the card, the balls it starts
	# with (it read "Down 100" and "0 now" there)
	stats["balls_left"] = _tray_count()
	return stats


# The balls the tray shows now: before the game starts, those it will start with.
func _tray_count() -> int:
	if _rules.state == PachinkoRules.State.INSTRUCTIONS:
		return _level.cup_start_balls
	return _cup.count()


func _on_tray_shown(_count: int) -> void:
	if _rules != null:
		show_now()
