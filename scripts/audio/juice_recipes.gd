class_name JuiceRecipes
extends RefCounted
## Recipes for the pachinko's juice (see scenes/pachinko/juice/): the slow-motion moment,
## the jackpot's camera thump and light sweep, the fever round's countdown and its brighter
## pin chime. sound_recipes.gd lists and builds them with the rest, so a SoundBank plays
## them by name like any other sound.

## Time slows for a ball about to drop into a pocket: a deep falling "whoom".
const SLOW_MO := &"slow_mo"
## The jackpot's camera nudge: a low drum hit that shakes the cabinet.
const JACKPOT_THUMP := &"jackpot_thump"
## The light sweeping across the board on a jackpot: a rising glassy shimmer.
const LIGHT_SWEEP := &"light_sweep"
## One of the fever round's last seconds ticking away: a short bright double beep.
const FEVER_TICK := &"fever_tick"
## A pin struck while fever is on: the tick with a bell on top, higher and warmer.
const PIN_FEVER := &"pin_fever"


## Every juice recipe name, in a stable order.
static func names() -> Array[StringName]:
	return [SLOW_MO, JACKPOT_THUMP, LIGHT_SWEEP, FEVER_TICK, PIN_FEVER]


## True when `sound` is one of these recipes.
static func has(sound: StringName) -> bool:
	return sound in names()


## Builds the named clip; null for a name that is not a juice recipe.
static func build(sound: StringName) -> AudioStreamWAV:
	match sound:
		SLOW_MO:
			return SoundSynth.to_stream(_slow_mo(), 0.75)
		JACKPOT_THUMP:
			return SoundSynth.to_stream(_thump(), 0.9)
		LIGHT_SWEEP:
			return SoundSynth.to_stream(_shimmer(), 0.55)
		FEVER_TICK:
			return SoundSynth.to_stream(_fever_tick(), 0.6)
		PIN_FEVER:
			return SoundSynth.to_stream(_pin_fever(), 0.8)
	return null


## A low tone sliding down an octave and a half under a soft breath of noise: the sound of
## time stretching.
static func _slow_mo() -> PackedFloat32Array:
	var fall := SoundSynth.sweep(0.7, 330.0, 110.0, 0.8, 3.2)
	var under := SoundSynth.sweep(0.7, 165.0, 55.0, 0.5, 2.6)
	var breath := SoundSynth.noise(0.6, 0.25, 4.0, 0.96, 41)
	return SoundSynth.mix([fall, under, breath])


## A drum hit: a body that drops in pitch fast, a sub thump and a short slap of noise.
static func _thump() -> PackedFloat32Array:
	var body := SoundSynth.sweep(0.35, 120.0, 48.0, 1.0, 9.0)
	var sub := SoundSynth.partials(0.45, [_p(55.0, 0.7, 7.0), _p(82.0, 0.3, 11.0)])
	var slap := SoundSynth.noise(0.05, 0.6, 60.0, 0.4, 42)
	return SoundSynth.mix([body, sub, slap])


## Glass bells one after another up a bright scale, each a little softer, over a rising
## airy hiss: light running across the glass.
static func _shimmer() -> PackedFloat32Array:
	var notes: Array[float] = [1319.0, 1568.0, 1760.0, 2093.0, 2349.0, 2637.0, 3136.0]
	var out := SoundSynth.noise(0.8, 0.12, 2.5, 0.3, 43)
	for i in notes.size():
		var f := notes[i]
		var amp := 0.6 - 0.05 * i
		var bell := SoundSynth.partials(0.3, [_p(f, amp, 12.0), _p(f * 2.01, amp * 0.3, 18.0)])
		SoundSynth.overlay(out, bell, 0.07 * i)
	return out


## Two short high beeps, like a machine's timer.
static func _fever_tick() -> PackedFloat32Array:
	var beep := SoundSynth.partials(0.07, [_p(1760.0, 1.0, 40.0), _p(3520.0, 0.25, 60.0)])
	var out := beep.duplicate()
	SoundSynth.overlay(out, beep, 0.09)
	return out


## The pin tick's bright ping with a small bell a fifth above it.
static func _pin_fever() -> PackedFloat32Array:
	var ping := SoundSynth.partials(0.12, [_p(3520.0, 1.0, 45.0), _p(5280.0, 0.4, 60.0)])
	var bell := SoundSynth.partials(0.2, [_p(2637.0, 0.5, 20.0)])
	return SoundSynth.mix([ping, bell])


static func _p(freq: float, amp: float, decay: float) -> PackedFloat32Array:
	return PackedFloat32Array([freq, amp, decay])
