class_name AimPreview
extends Node2D
## While the player aims, the flight a shot at that power takes: a dotted line from the
## rail's mouth to a ring where the ball first meets a pin (LaunchPreview: the game's own
## physics, a lone ball). It shows while the flipper is drawn back (at the drawback's power)
## and while the handle is held or for SHOW_AFTER_TURN seconds after it was turned (at the
## handle's strength, with two faint rings where its spring's spread, LaunchHandle.JITTER
## either side, may send a ball). Nothing shows while no one aims.

## Seconds the handle's preview stays after it was turned (a turn is aiming too).
const SHOW_AFTER_TURN := 1.5
## Seconds the preview takes to fade in or out.
const FADE_SECONDS := 0.15
## Board pixels between two dots of the flight.
const DOT_GAP := 9.0
const DOT := Color(1.0, 1.0, 1.0, 0.8)
const DOT_SHADE := Color(0.05, 0.02, 0.12, 0.6)
const LANDING := Color("ffd34d")

## True while a big moment (a jackpot or round banner, or the reach stage while the player
## does not aim) holds the board: the flight is hidden (a play trial saw the dots drawn over
## the ROUND banner). PachinkoGame sets it every frame from BonusView.holds_the_aim().
var held_back := false

var _rules: PachinkoRules
var _preview: LaunchPreview
var _previewed: BoardLevel
## The power shown (or fading out), and how visible it is, 0..1.
var _power := 0.0
var _handle := false
var _alpha := 0.0
var _turned_left := 0.0
var _handle_power := -1.0
## The worker task measuring the flights (-1: none running), and what it measured.
var _task := -1
var _measured: LaunchPreview


# Takes the measured flights once the task is done (`wait`: waits for it).
func _collect(wait := false) -> void:
	if _task < 0 or not (wait or WorkerThreadPool.is_task_completed(_task)):
		return
	WorkerThreadPool.wait_for_task_completion(_task)
	_task = -1
	_preview = _measured
	_measured = null


func _exit_tree() -> void:
	_collect(true)  # a task still running must not outlive the screen


## Shows the aim of `rules`; the flights are measured once per board, on a worker thread
## (about a second on a slow machine: the screen opens meanwhile, and the preview shows
## once they are in).
func bind(rules: PachinkoRules) -> void:
	_rules = rules
	if _previewed != rules.level:
		_collect()
		_preview = null
		_previewed = rules.level
		var level := rules.level
		_task = WorkerThreadPool.add_task(
			func() -> void: _measured = LaunchPreview.measure(level), false, "aim preview"
		)
	_handle_power = rules.handle.power
	_turned_left = 0.0
	_alpha = 0.0
	set_process(true)
	queue_redraw()


## The flights this layer draws from (waits for their measurement if it is still running).
func preview() -> LaunchPreview:
	_collect(true)
	return _preview


## The power being aimed now, or -1 when the player is not aiming.
func aimed_power() -> float:
	if _rules == null or _rules.state != PachinkoRules.State.PLAYING:
		return -1.0
	if _rules.drawing:
		return _rules.power
	if _rules.handle.held or _turned_left > 0.0:
		return _rules.handle.power
	return -1.0


## True while the flight is on screen (fading out included).
func is_showing() -> bool:
	return _alpha > 0.0


## The power of the flight on screen (the last one aimed while it fades out).
func shown_power() -> float:
	return _power


func _ready() -> void:
	set_process(false)


func _process(delta: float) -> void:
	_collect()
	if _rules == null:
		return
	if _rules.handle.power != _handle_power:
		_handle_power = _rules.handle.power
		_turned_left = SHOW_AFTER_TURN
	_turned_left = maxf(_turned_left - delta, 0.0)
	var aimed := -1.0 if held_back else aimed_power()
	if aimed >= 0.0:
		_power = aimed
		_handle = not _rules.drawing
		_alpha = minf(_alpha + delta / FADE_SECONDS, 1.0)
	else:
		_alpha = maxf(_alpha - delta / FADE_SECONDS, 0.0)
	queue_redraw()


func _draw() -> void:
	if _preview == null or _alpha <= 0.0:
		return
	var path := _preview.path(_power)
	var walked := 0.0
	var next_dot := 0.0
	for i in range(1, path.size()):
		var a := path[i - 1]
		var b := path[i]
		var length := a.distance_to(b)
		while next_dot <= walked + length:
			var at := a.lerp(b, (next_dot - walked) / maxf(length, 0.001))
			draw_circle(at, 3.2, Color(DOT_SHADE, DOT_SHADE.a * _alpha), true, -1.0, true)
			draw_circle(at, 2.2, Color(DOT, DOT.a * _alpha), true, -1.0, true)
			next_dot += DOT_GAP
		walked += length
	var landing := _preview.landing(_power)
	if _handle:
		for side: float in [-1.0, 1.0]:
			var spread := _preview.landing(_power + side * LaunchHandle.JITTER)
			draw_arc(spread, 6.0, 0.0, TAU, 20, Color(LANDING, 0.45 * _alpha), 1.5, true)
	draw_arc(landing, 9.0, 0.0, TAU, 24, Color(DOT_SHADE, DOT_SHADE.a * _alpha), 5.0, true)
	draw_arc(landing, 9.0, 0.0, TAU, 24, Color(LANDING, 0.95 * _alpha), 2.5, true)
