class_name CameraNudge
extends Node
## The jackpot's camera nudge: the board jolts as if the cabinet took a thump, swings
## back and forth a few times, each smaller, and is back at rest after SECONDS. Moves only
## the picture (BoardView.nudge), never a ball. With screen shake off in the settings the
## board stays still and only the thump is heard.

## Real seconds from the kick to rest.
const SECONDS := 0.6
## Screen pixels of the first swing.
const AMPLITUDE := 11.0
## Swings a second along the kick and across it (different, so the jolt is not a line).
const ALONG_HZ := 9.0
const ACROSS_HZ := 6.5
## Share of the swing across the kick.
const ACROSS_SHARE := 0.35
## How fast the swings die down (per second).
const DAMPING := 6.0

## False when the player turned screen shake off: kicks only sound.
var enabled := true

var _target: BoardView
var _sounds: SoundBank
var _direction := Vector2.DOWN
var _age := SECONDS


## Nudges `target` and plays the thump on `sounds` (null: silent).
func attach(target: BoardView, sounds: SoundBank) -> void:
	_target = target
	_sounds = sounds


func _ready() -> void:
	set_process(false)


## Kicks the board along `direction` (mostly down: the cabinet was struck from above).
func kick(direction: Vector2 = Vector2(0.3, 1.0)) -> void:
	if _sounds != null:
		_sounds.play(SoundBank.JACKPOT_THUMP, -2.0)
	if not enabled:
		return
	_direction = direction.normalized() if direction != Vector2.ZERO else Vector2.DOWN
	_age = 0.0
	set_process(true)


## True while the board is away from rest.
func is_moving() -> bool:
	return _age < SECONDS


## The board's offset `age` real seconds after a kick along `direction`.
static func offset_at(age: float, direction: Vector2) -> Vector2:
	if age < 0.0 or age >= SECONDS:
		return Vector2.ZERO
	# The last tenth fades to exactly nothing, so rest is reached without a jump.
	var fade := exp(-DAMPING * age) * clampf((SECONDS - age) / (SECONDS * 0.1), 0.0, 1.0)
	var across := direction.orthogonal()
	var swing := direction * sin(TAU * ALONG_HZ * age)
	swing += across * ACROSS_SHARE * sin(TAU * ACROSS_HZ * age)
	return swing * AMPLITUDE * fade


func _process(delta: float) -> void:
	_age += delta
	if _target != null:
		_target.nudge = offset_at(_age, _direction)
	if not is_moving():
		if _target != null:
			_target.nudge = Vector2.ZERO
		set_process(false)
