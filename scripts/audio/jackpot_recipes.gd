class_name JackpotRecipes
extends RefCounted
## Recipes for the jackpot's big moments (scenes/pachinko/bonus/): the reach's rising tone
## while the last reel slows, the jackpot's fanfare, and the bell that opens each round.
## sound_recipes.gd lists and builds them with the rest, so a SoundBank plays them by name.

## A reach: a tone and its fifth rising for as long as the last reel slows, with a pulse
## that quickens, the machine holding its breath.
const REACH_RISE := &"reach_rise"
## The jackpot: a brass-like fanfare, three short calls and a long held chord.
const JACKPOT_FANFARE := &"jackpot_fanfare"
## A jackpot round opens: two bright bells a fourth apart.
const ROUND_BELL := &"round_bell"
## Seconds the reach's rising tone lasts (about the reach's length on screen).
const REACH_SECONDS := 3.2


## Every jackpot recipe name, in a stable order.
static func names() -> Array[StringName]:
	return [REACH_RISE, JACKPOT_FANFARE, ROUND_BELL]


## True when `sound` is one of these recipes.
static func has(sound: StringName) -> bool:
	return sound in names()


## Builds the named clip; null for a name that is not a jackpot recipe.
static func build(sound: StringName) -> AudioStreamWAV:
	match sound:
		REACH_RISE:
			return SoundSynth.to_stream(_reach_rise(), 0.7)
		JACKPOT_FANFARE:
			return SoundSynth.to_stream(_fanfare(), 0.85)
		ROUND_BELL:
			return SoundSynth.to_stream(_round_bell(), 0.7)
	return null


## Two slow glides up an octave a fifth apart, swelling, with a tremolo that speeds up.
static func _reach_rise() -> PackedFloat32Array:
	var low := SoundSynth.sweep(REACH_SECONDS, 220.0, 440.0, 0.6, 0.0)
	var high := SoundSynth.sweep(REACH_SECONDS, 330.0, 660.0, 0.35, 0.0)
	var out := SoundSynth.mix([low, high])
	var rate := float(SoundSynth.SAMPLE_RATE)
	var phase := 0.0
	for i in out.size():
		var t := i / rate
		var share := t / REACH_SECONDS
		phase += (4.0 + 14.0 * share) / rate
		var swell := 0.35 + 0.65 * share
		out[i] *= swell * (0.7 + 0.3 * sin(TAU * phase))
	return out


## Da-da-daa, da-da-daa, then a held major chord: each note a bright buzzy tone (odd and
## even partials, like a trumpet), the chord with a slow vibrato-free swell and fade.
static func _fanfare() -> PackedFloat32Array:
	var calls: Array[Array] = [
		[0.0, 523.0, 0.12],
		[0.14, 523.0, 0.12],
		[0.28, 784.0, 0.3],
		[0.62, 659.0, 0.12],
		[0.76, 659.0, 0.12],
		[0.9, 1047.0, 0.3],
	]
	var out := PackedFloat32Array()
	out.resize(int(2.6 * SoundSynth.SAMPLE_RATE))
	for note: Array in calls:
		var at: float = note[0]
		var pitch: float = note[1]
		var length: float = note[2]
		SoundSynth.overlay(out, _brass(pitch, length, 8.0), at)
	for f: float in [523.0, 659.0, 784.0, 1047.0]:
		SoundSynth.overlay(out, _brass(f, 1.3, 1.6), 1.25)
	return out


static func _round_bell() -> PackedFloat32Array:
	var first := SoundSynth.partials(0.5, [_p(1568.0, 1.0, 7.0), _p(3136.0, 0.35, 11.0)])
	var second := SoundSynth.partials(0.6, [_p(2093.0, 1.0, 6.0), _p(4186.0, 0.3, 10.0)])
	SoundSynth.overlay(first, second, 0.12)
	return first


# A trumpet-like note of `seconds`: a stack of partials, decaying at `decay` per second.
static func _brass(freq: float, seconds: float, decay: float) -> PackedFloat32Array:
	var parts: Array[PackedFloat32Array] = []
	for k in 6:
		parts.append(_p(freq * (k + 1), 0.9 / (k + 1.0), decay + k * 1.5))
	return SoundSynth.partials(seconds, parts)


static func _p(freq: float, amp: float, decay: float) -> PackedFloat32Array:
	return PackedFloat32Array([freq, amp, decay])
