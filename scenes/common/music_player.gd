class_name MusicPlayer
extends Node
## Plays a pachinko machine's music loop on the "Music" bus (whose volume is the Music
## setting) and changes it with the game's mood: `set_mood(&"reach")` when two reels match,
## `&"jackpot"` on a jackpot, `&"normal"` after. A change crossfades into the other loop over
## FADE_SECONDS. The loops come from MusicBank, built on a worker thread: the music starts
## when the first is ready, never holding up a frame. Headless runs (tests, the autoplay)
## build and play nothing: `enabled` is false there, and the mood is only remembered.

const NORMAL := MusicRecipes.NORMAL
const REACH := MusicRecipes.REACH
const JACKPOT := MusicRecipes.JACKPOT
const BUS := &"Music"
## Seconds a mood change takes to fade from one loop into the other.
const FADE_SECONDS := 0.8
## Quietest a fading loop gets before it stops, dB.
const SILENT_DB := -60.0
## Seconds after play_machine before the loops start building: the board's own loading and
## first frames get the processor first (on two cores the build slowed them by a second).
const BUILD_DELAY := 1.0

## Builds and plays music; false in headless runs (set before the node enters the tree to
## override).
var enabled := DisplayServer.get_name() != "headless"

var _machine := ""
var _mood := NORMAL
var _players: Array[AudioStreamPlayer] = []
var _active := 0
var _fade: Tween
var _build_wait := 0.0


func _ready() -> void:
	var bus := BUS if AudioServer.get_bus_index(BUS) >= 0 else &"Master"
	for i in 2:
		var player := AudioStreamPlayer.new()
		player.bus = bus
		add_child(player)
		_players.append(player)
	set_process(false)


## Plays the music of `machine` (a board's fascia name; Classic's for one without its own),
## in the current mood, as soon as its loop is built.
func play_machine(fascia: String) -> void:
	_machine = fascia if MusicRecipes.STYLES.has(fascia) else FasciaNames.CLASSIC
	if enabled:
		_build_wait = 0.0 if MusicBank.is_requested(_machine) else BUILD_DELAY
		set_process(true)


## The machine whose music plays ("" before play_machine).
func machine() -> String:
	return _machine


## The mood the music is in (NORMAL, REACH or JACKPOT).
func mood() -> StringName:
	return _mood


## Changes the music's mood: NORMAL, REACH or JACKPOT. Any other name is refused with an
## error naming it and the mood stays as it was.
func set_mood(next: StringName) -> void:
	if not MusicRecipes.MOODS.has(next):
		push_error("MusicPlayer.set_mood: no mood '%s' (normal, reach or jackpot)" % next)
		return
	if next == _mood:
		return
	_mood = next
	if enabled and not _machine.is_empty():
		set_process(true)


## The stream now playing (null before the first loop is ready, or when disabled).
func playing_stream() -> AudioStreamWAV:
	if _players.is_empty() or not _players[_active].playing:
		return null
	return _players[_active].stream as AudioStreamWAV


# Starts the build after BUILD_DELAY, waits for the wanted loop, then fades into it; sleeps
# once it plays.
func _process(delta: float) -> void:
	if _build_wait > 0.0:
		_build_wait -= delta
		return
	MusicBank.request(_machine)
	var wanted := MusicBank.loop(_machine, _mood)
	if wanted == null:
		return
	set_process(false)
	if playing_stream() == wanted:
		return
	var old := _players[_active]
	var first := not old.playing
	_active = 1 - _active
	var incoming := _players[_active]
	incoming.stream = wanted
	incoming.volume_db = 0.0 if first else SILENT_DB
	incoming.play()
	if first:
		return
	if _fade != null:
		_fade.kill()
	_fade = create_tween().set_parallel()
	_fade.tween_property(incoming, "volume_db", 0.0, FADE_SECONDS)
	_fade.tween_property(old, "volume_db", SILENT_DB, FADE_SECONDS)
	_fade.chain().tween_callback(old.stop)
