class_name RestartPrompt
extends RulesReminder
## The question R asks before it throws a session away: "New game? Your 80 balls go." over
## the top of the board, answered by R again (the game starts over) or Esc (it goes, the
## game goes on); it goes by itself after ASK_SECONDS. A play trial lost a cup of 80 balls
## to one stray R. Only a session with something to lose asks (wants_asking).

## Seconds the question waits for its answer. Trial 6: at 4 s a second R "about 2 s later"
## (on a 16 FPS box, between screenshots) came after the question had gone, asked it again
## and looked ignored; 10 s leaves a player time to read it and answer.
const ASK_SECONDS := 10.0

# The balls the question names now (-1: not asked yet).
var _balls := -1


func _init() -> void:
	super()
	shown_seconds = ASK_SECONDS


## True when starting over would throw something away: balls won (more to shoot than the
## `start_balls` the game began with, or any paid back), or more than one shot in.
static func wants_asking(stats: Dictionary, start_balls: int) -> bool:
	return (
		stats.get("balls_left", 0) > start_balls
		or stats.get("game_payouts", 0) > 0
		or stats.get("game_shots", 0) > 1
	)


## The balls a new game would throw away: those the player holds, the tray's count (a ball
## in flight is not held: trial 8 read "Your 80 balls go" beside a tray of 79).
static func balls_at_stake(stats: Dictionary) -> int:
	return stats.get("balls_left", 0)


## Asks whether to start over, naming the `balls` the player would lose.
func ask(balls: int) -> void:
	_balls = balls
	show_line(_words(balls))


## Keeps the question's count on the player's `balls` while it is up: balls in the air land
## and pay after R (trial 9 read "Your 79 balls go" while the tray went to 81, then 85).
func follow(balls: int) -> void:
	if asking() and balls != _balls:
		_balls = balls
		retext(_words(balls))


## The balls the question names now.
func balls_named() -> int:
	return _balls


static func _words(balls: int) -> String:
	return (
		"New game? Your [b]%d[/b] ball%s go.\n[b]%s[/b] again: new game   [b]%s[/b]: keep playing"
		% [
			balls,
			"" if balls == 1 else "s",
			PlainMarkup.escape(KeyNames.of(&"game_restart", "the restart key")),
			PlainMarkup.escape(KeyNames.of(&"pause", "Esc")),
		]
	)


## True while the question is up (a second R starts over).
func asking() -> bool:
	return visible and modulate.a > 0.0


# Esc answers the question (keep playing) instead of opening the pause menu.
func _unhandled_input(event: InputEvent) -> void:
	if asking() and (event.is_action_pressed("pause") or event.is_action_pressed("ui_cancel")):
		dismiss()
		get_viewport().set_input_as_handled()
