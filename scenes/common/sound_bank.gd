class_name SoundBank
extends Node
## Procedurally generated sound effects on the "SFX" bus ("Master" when there is none).
## Add one to a scene and call `play()` or `play_impact()`; the clips are built by code
## (see sound_recipes.gd) once per process and shared by every bank. Overall volume is the
## bus volume, which the settings own.

## Names of the sounds, re-exported so callers can write `SoundBank.PIN_TICK`.
const PIN_TICK := SoundRecipes.PIN_TICK
const LAUNCH := SoundRecipes.LAUNCH
const POCKET_WIN := SoundRecipes.POCKET_WIN
const DRAIN := SoundRecipes.DRAIN
const BALL_RETURN := SoundRecipes.BALL_RETURN
const GAME_OVER := SoundRecipes.GAME_OVER
const WALL_THUD := SoundRecipes.WALL_THUD
const GOAL_CHIME := SoundRecipes.GOAL_CHIME
const HOLE_FALL := SoundRecipes.HOLE_FALL
const FANFARE := SoundRecipes.FANFARE
const UI_CLICK := SoundRecipes.UI_CLICK
const REEL_STOP := SoundRecipes.REEL_STOP
const JACKPOT := SoundRecipes.JACKPOT
const TULIP_OPEN := SoundRecipes.TULIP_OPEN
const START_CATCH := SoundRecipes.START_CATCH
const FEVER_END := SoundRecipes.FEVER_END
const SLOW_MO := JuiceRecipes.SLOW_MO
const JACKPOT_THUMP := JuiceRecipes.JACKPOT_THUMP
const LIGHT_SWEEP := JuiceRecipes.LIGHT_SWEEP
const FEVER_TICK := JuiceRecipes.FEVER_TICK
const PIN_FEVER := JuiceRecipes.PIN_FEVER
const REACH_RISE := JackpotRecipes.REACH_RISE
const JACKPOT_FANFARE := JackpotRecipes.JACKPOT_FANFARE
const ROUND_BELL := JackpotRecipes.ROUND_BELL
## The sounds a pachinko game plays in its first seconds, built while it loads.
const PACHINKO_FIRST_SOUNDS: Array[StringName] = [
	PIN_TICK, LAUNCH, POCKET_WIN, DRAIN, BALL_RETURN, GAME_OVER, WALL_THUD
]

const PREFERRED_BUS := &"SFX"
const FALLBACK_BUS := &"Master"
## Quietest and loudest volume an impact maps to.
const IMPACT_QUIET_DB := -26.0
const IMPACT_LOUD_DB := -2.0

static var _cache: Dictionary[StringName, AudioStreamWAV] = {}
# The cache is shared with the worker of warm_in_background: every read and write holds it.
static var _cache_lock := Mutex.new()
static var _background_task := -1

## Voices playing at once; the oldest is cut when all are busy.
@export var voices: int = 12
## Shortest gap between two impact sounds of the same name, in milliseconds.
@export var impact_interval_ms: int = 28

var _players: Array[AudioStreamPlayer] = []
var _next_voice := 0
var _last_impact_ms: Dictionary[StringName, int] = {}
var _played := 0


func _ready() -> void:
	var bus := bus_name()
	for i in maxi(voices, 1):
		var player := AudioStreamPlayer.new()
		player.bus = bus
		add_child(player)
		_players.append(player)


## The bus sounds go to: "SFX" when the project's bus layout has it, else "Master".
static func bus_name() -> StringName:
	if AudioServer.get_bus_index(PREFERRED_BUS) >= 0:
		return PREFERRED_BUS
	return FALLBACK_BUS


## The generated clip for `sound` (built on first use, then cached); null when unknown.
static func stream(sound: StringName) -> AudioStreamWAV:
	_cache_lock.lock()
	var cached: AudioStreamWAV = _cache.get(sound)
	_cache_lock.unlock()
	if cached != null:
		return cached
	# built here when the worker has not got to it yet (built twice at worst, never wrong)
	var built := SoundRecipes.build(sound)
	if built == null:
		return null
	_cache_lock.lock()
	_cache[sound] = built
	_cache_lock.unlock()
	return built


## Builds the given sounds now (a scene calls this while loading, so the first pocket win
## does not stall a frame building its jingle).
static func warm(sounds: Array[StringName]) -> void:
	for sound in sounds:
		stream(sound)


## Builds the given sounds on a worker thread, so a screen that needs them later finds them
## ready (the game does this at start: they took 0.2 s of a board's loading). Once per run;
## a later call while the first still runs does nothing.
static func warm_in_background(sounds: Array[StringName]) -> void:
	if _background_task >= 0:
		return
	var wanted := sounds.duplicate()
	_background_task = WorkerThreadPool.add_task(
		func() -> void:
			for sound: StringName in wanted:
				stream(sound),
		false,
		"SoundBank.warm_in_background"
	)


## Waits for the worker of warm_in_background (the game calls it as it quits).
static func wait_for_background() -> void:
	if _background_task >= 0:
		WorkerThreadPool.wait_for_task_completion(_background_task)
		_background_task = -1


## Plays a sound at `volume_db` and `pitch`. Returns false for an unknown sound.
func play(sound: StringName, volume_db: float = 0.0, pitch: float = 1.0) -> bool:
	var clip := stream(sound)
	if clip == null or _players.is_empty():
		return false
	var player := _players[_next_voice]
	_next_voice = (_next_voice + 1) % _players.size()
	player.stream = clip
	player.volume_db = volume_db
	player.pitch_scale = clampf(pitch, 0.25, 4.0)
	player.play()
	_played += 1
	return true


## Plays an impact whose pitch and volume rise with `speed` between `min_speed` (silent
## below it) and `max_speed`. Rate-limited per sound: returns false when skipped.
## `now_ms` lets tests drive the clock; by default it is the engine's.
func play_impact(
	sound: StringName, speed: float, min_speed: float, max_speed: float, now_ms: int = -1
) -> bool:
	if speed < min_speed or max_speed <= min_speed:
		return false
	var now := Time.get_ticks_msec() if now_ms < 0 else now_ms
	var last: int = _last_impact_ms.get(sound, -1000000)
	if now - last < impact_interval_ms:
		return false
	_last_impact_ms[sound] = now
	var t := clampf((speed - min_speed) / (max_speed - min_speed), 0.0, 1.0)
	return play(sound, lerpf(IMPACT_QUIET_DB, IMPACT_LOUD_DB, t), lerpf(0.85, 1.3, t))


## How many sounds this bank has started (tests and the stats overlay read it).
func played_count() -> int:
	return _played
