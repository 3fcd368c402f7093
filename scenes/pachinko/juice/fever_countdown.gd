class_name FeverCountdown
extends Node
## The fever round's last seconds are heard: while an attacker is open, each of its last
## LAST_SECONDS whole seconds starts with a double beep, so a player feeding it knows the
## lid is about to shut without looking away from the balls. Reads BonusMachine once a
## frame; changes nothing.

## The seconds at the end of a round that beep.
const LAST_SECONDS := 3

## Beeps played since the game scene started (tests read it).
var beeps := 0

var _machine: BonusMachine
var _sounds: SoundBank
## The whole second last heard per bonus pocket (0: none yet this round).
var _heard := PackedInt32Array()


## Counts down the attackers of `machine`, beeping on `sounds` (null: silent).
func bind(machine: BonusMachine, bonus_count: int, sounds: SoundBank) -> void:
	_machine = machine
	_sounds = sounds
	_heard = PackedInt32Array()
	_heard.resize(bonus_count)
	set_process(bonus_count > 0)


func _process(_delta: float) -> void:
	check()


## Beeps when an open attacker has just entered one of its last seconds.
func check() -> void:
	if _machine == null:
		return
	for i in _heard.size():
		var second := ceili(_machine.time_left(i)) if _machine.is_open(i) else 0
		if second > 0 and second <= LAST_SECONDS and second != _heard[i]:
			beeps += 1
			if _sounds != null:
				_sounds.play(SoundBank.FEVER_TICK, -6.0, 1.0 + 0.06 * (LAST_SECONDS - second))
		_heard[i] = second
