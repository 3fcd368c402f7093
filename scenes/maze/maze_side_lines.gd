class_name MazeSideLines
extends RefCounted
## The side panel's changing lines while a board is played: the mode, the clock and the best
## time, the medal still in reach, and the goal count (with its red flash when a ball is
## lost). The maze screen tells it what happened; it says it in words.

## The count flashes this long when a ball is lost (seconds), in the hard colour.
const LOST_FLASH_SECONDS := 1.2
const LOST_FLASH := Color(0.85, 0.15, 0.2)

## The medal line past bronze once the board has a best time in this mode.
const TOO_SLOW := "Too slow for a medal: finish anyway!"
## ...and before its first finish: a first run is for finding the way in.
const FIRST_RUN := "First run: just find the way in!"

var _mode: Label
var _timer: Label
var _best: Label
var _next_medal: Label
var _in_goal: Label
## Seconds left of the count's flash after a ball was lost (0: none).
var _count_flash_left := 0.0


## The panel's labels: the mode, the clock, the best time, the medal line, the goal count.
func _init(mode: Label, timer: Label, best: Label, next_medal: Label, in_goal: Label) -> void:
	_mode = mode
	_timer = timer
	_best = best
	_next_medal = next_medal
	_in_goal = in_goal


## A new attempt in easy or `hard` mode: the mode, no balls in yet of `total`.
func show_attempt(hard: bool, total: int) -> void:
	_stop_count_flash()
	show_goal_count(0, total)
	_mode.text = "HARD MODE" if hard else "EASY MODE"
	_mode.modulate = MazePalette.HARD if hard else MazePalette.GOAL


## Shows the clock at `rules.elapsed` and, while the game runs, the medal still in reach.
func show_clock(rules: MazeRules) -> void:
	_timer.text = "Time  %s" % MazeWinSummary.clock(rules.elapsed)
	if not rules.is_over():
		show_next_medal(rules)


## The medal still in reach while playing: "Gold by 0:36.3", then Silver once that passed;
## past bronze, TOO_SLOW, or FIRST_RUN before the board's first finish in this mode.
func show_next_medal(rules: MazeRules) -> void:
	var times := Medals.times_for(rules.level, rules.hard_mode)
	var target := Medals.next_target(times, rules.elapsed)
	var medal: Medals.Medal = target["medal"]
	var first_run := App.best_maze_time(rules.level.board_id, rules.hard_mode) < 0.0
	if times.size() != 3:
		_next_medal.text = ""
	elif medal == Medals.Medal.NONE and first_run:
		# a first run is for finding the way (trial 9: "Too slow for a medal" landed while
		# still exploring a new board, "a downer on a first look")
		_next_medal.text = FIRST_RUN
	elif medal == Medals.Medal.NONE:
		_next_medal.text = TOO_SLOW
	else:
		var seconds: float = target["seconds"]
		_next_medal.text = "%s by %s" % [Medals.name_of(medal), MazeWinSummary.clock(seconds)]


## Puts `line` in the medal line's place (the medal won, or nothing after a loss).
func show_medal_line(line: String) -> void:
	_next_medal.text = line


## The medal line as shown (for tests).
func medal_line() -> String:
	return _next_medal.text


## The best time on `board_id` in easy or `hard` mode, or "--" before a finish.
func show_best(board_id: String, hard: bool) -> void:
	var best := App.best_maze_time(board_id, hard)
	_best.text = "Best  %s" % (MazeWinSummary.clock(best) if best >= 0.0 else "--")


## Gives the Time and Best lines the width of a time shown in them, so "Best  --" and
## "Best  0:12.3" take the same room: the column, sized to its widest line, keeps its width
## after a first finish (a play trial saw the board and the joystick shrink on the next
## attempt).
func hold_time_widths() -> void:
	for label: Label in [_timer, _best]:
		var font := label.get_theme_font(&"font")
		var font_size := label.get_theme_font_size(&"font_size")
		var prefix := label.text.get_slice("  ", 0)
		var widest := font.get_string_size(
			prefix + "  0:00.0", HORIZONTAL_ALIGNMENT_LEFT, -1, font_size
		)
		label.custom_minimum_size.x = ceilf(widest.x)


## "In goal 2 / 4".
func show_goal_count(count: int, total: int) -> void:
	_in_goal.text = "In goal  %d / %d" % [count, total]


## Balls were lost: "2 of 4 balls left" (as the card says it), with a red flash the first
## time (`flash`).
func show_balls_left(left: int, total: int, flash: bool) -> void:
	_in_goal.text = MazeHints.balls_left(left, total)
	if flash:
		_count_flash_left = LOST_FLASH_SECONDS
		_in_goal.modulate = LOST_FLASH


## The goal count line as shown (for tests).
func goal_count_text() -> String:
	return _in_goal.text


## True while the count flashes (for tests).
func count_flashing() -> bool:
	return _count_flash_left > 0.0


## Steps the count's flash by `delta` seconds: three red pulses, then its own colour.
func step_flash(delta: float) -> void:
	if _count_flash_left <= 0.0:
		return
	_count_flash_left = maxf(_count_flash_left - delta, 0.0)
	var pulses := 3.0 * (1.0 - _count_flash_left / LOST_FLASH_SECONDS)
	var strength := 0.5 - 0.5 * cos(pulses * TAU)
	_in_goal.modulate = Color.WHITE.lerp(LOST_FLASH, strength)


func _stop_count_flash() -> void:
	_count_flash_left = 0.0
	_in_goal.modulate = Color.WHITE
