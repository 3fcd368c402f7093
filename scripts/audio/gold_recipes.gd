class_name GoldRecipes
extends RefCounted
## Recipes for the gold pins (scenes/pachinko/gold/): the bright chime of a gold pin put
## out and the rising peal of a set's prize. sound_recipes.gd lists and builds them with
## the rest, so a SoundBank plays them by name like any other sound.

## A gold pin put out: a bright two-bell chime, well above the pins' ticks.
const GOLD_CHIME := &"gold_chime"
## A set's last gold pin: a quick peal of bells climbing an octave.
const GOLD_PRIZE := &"gold_prize"


## Every gold recipe name, in a stable order.
static func names() -> Array[StringName]:
	return [GOLD_CHIME, GOLD_PRIZE]


## True when `sound` is one of these recipes.
static func has(sound: StringName) -> bool:
	return sound in names()


## Builds the named clip; null for a name that is not a gold recipe.
static func build(sound: StringName) -> AudioStreamWAV:
	match sound:
		GOLD_CHIME:
			return SoundSynth.to_stream(_chime(), 0.75)
		GOLD_PRIZE:
			return SoundSynth.to_stream(_peal(), 0.8)
	return null


# Two bells a sixth apart, the second a beat later, each with a glassy upper partial.
static func _chime() -> PackedFloat32Array:
	var low := SoundSynth.partials(0.35, [_p(2093.0, 0.8, 9.0), _p(4186.0, 0.25, 16.0)])
	var high := SoundSynth.partials(0.4, [_p(3520.0, 0.7, 8.0), _p(7040.0, 0.15, 14.0)])
	var out := low.duplicate()
	SoundSynth.overlay(out, high, 0.06)
	return out


# Bells up a major arpeggio over an octave, then the top one held a little longer.
static func _peal() -> PackedFloat32Array:
	var notes: Array[float] = [1047.0, 1319.0, 1568.0, 2093.0, 2637.0, 3136.0, 4186.0]
	var out := PackedFloat32Array()
	for i in notes.size():
		var f := notes[i]
		var last := i == notes.size() - 1
		var bell := SoundSynth.partials(
			0.6 if last else 0.3, [_p(f, 0.6, 5.0 if last else 11.0), _p(f * 2.0, 0.2, 16.0)]
		)
		SoundSynth.overlay(out, bell, 0.055 * i)
	return out


static func _p(freq: float, amp: float, decay: float) -> PackedFloat32Array:
	return PackedFloat32Array([freq, amp, decay])
