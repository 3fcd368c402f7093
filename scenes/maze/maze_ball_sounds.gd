class_name MazeBallSounds
extends Node
## The maze's rolling sound, Labyrinth's signature: one looping player per ball whose
## loudness and pitch follow that ball's speed, silent when it rests. Call `update` every
## frame with the balls' velocities; `stop_all` on a win, a loss or a reset.

## Below this speed (px/s) a ball is silent; at `LOUD_SPEED` it is as loud as it gets.
const QUIET_SPEED := 4.0
const LOUD_SPEED := 110.0
## Volume and pitch at the quiet and loud ends.
const QUIET_DB := -34.0
const LOUD_DB := -9.0
const LOW_PITCH := 0.6
const HIGH_PITCH := 1.35
## How fast the volume follows the speed (1/s): smooth, but quick enough for a wall stop.
const FOLLOW_RATE := 18.0

var _players: Array[AudioStreamPlayer] = []
var _levels: PackedFloat32Array = PackedFloat32Array()


## The loudness share 0..1 a ball rolling at `speed` px/s gets (0 = silent).
static func loudness(speed: float) -> float:
	if not is_finite(speed) or speed <= QUIET_SPEED:
		return 0.0
	return clampf((speed - QUIET_SPEED) / (LOUD_SPEED - QUIET_SPEED), 0.0, 1.0)


## The playback pitch for a ball rolling at `speed` px/s.
static func pitch(speed: float) -> float:
	return lerpf(LOW_PITCH, HIGH_PITCH, loudness(speed))


## Sets each ball's loop from its velocity (px/s); extra players stop, missing ones are made.
func update(velocities: PackedVector2Array, delta: float) -> void:
	while _players.size() < velocities.size():
		_add_player()
	var follow := 1.0 - exp(-FOLLOW_RATE * maxf(delta, 0.0))
	for i in _players.size():
		var speed := velocities[i].length() if i < velocities.size() else 0.0
		var target := loudness(speed)
		_levels[i] = lerpf(_levels[i], target, follow)
		var player := _players[i]
		if _levels[i] < 0.01:
			if player.playing:
				player.stop()
			continue
		player.volume_db = lerpf(QUIET_DB, LOUD_DB, sqrt(_levels[i]))
		player.pitch_scale = pitch(speed)
		if not player.playing:
			player.play(randf() * SoundRecipes.ROLL_LOOP_SECONDS)


## Silences every ball at once.
func stop_all() -> void:
	for i in _players.size():
		_players[i].stop()
		_levels[i] = 0.0


## How many balls are audible now (for tests).
func audible_count() -> int:
	var count := 0
	for player in _players:
		if player.playing:
			count += 1
	return count


## The volume of ball `index`'s loop in dB (for tests); -80 when silent or unknown.
func volume_of(index: int) -> float:
	if index < 0 or index >= _players.size() or not _players[index].playing:
		return -80.0
	return _players[index].volume_db


func _add_player() -> void:
	var player := AudioStreamPlayer.new()
	player.stream = SoundBank.stream(SoundRecipes.BALL_ROLL)
	player.bus = SoundBank.bus_name()
	add_child(player)
	_players.append(player)
	_levels.append(0.0)
