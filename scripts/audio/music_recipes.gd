class_name MusicRecipes
extends RefCounted
## Each pachinko machine's tune, written as code and synthesised like the sound effects
## (sound_synth.gd): four bars over a chord progression, a melody drawn from the machine's
## scale by a fixed seed, a bass, a quiet arpeggio and light percussion, in the machine's own
## voices (a koto pluck for Classic, a marimba for Country, a music box for the Garden, a
## bright synth for Neon, temple bells for Sakura). One loop per machine and mood:
## - NORMAL: the tune as it idles along;
## - REACH: two reels match: faster, a tone higher, the arpeggio in sixteenths over pulsing
##   bass and hi-hats, and a rising line into the loop's end (the wait for the last reel);
## - JACKPOT: a fourth higher and faster still, the melody doubled an octave up in bells,
##   with a kick on every beat.
## `build` returns a seamless AudioStreamWAV loop; it takes a second or so in GDScript, so
## MusicBank runs it on a worker thread once per machine and keeps the result.

const NORMAL := &"normal"
const REACH := &"reach"
const JACKPOT := &"jackpot"
## The moods, in the order they are built (the one that plays first, first).
const MOODS: Array[StringName] = [NORMAL, REACH, JACKPOT]
const BARS := 4
const BEATS_PER_BAR := 4
## Longest a plucked note rings, seconds (the notes are cached and overlaid, so this bounds
## the work per note).
const RING_SECONDS := 0.45
const BASS_SECONDS := 0.5
const RATE := SoundSynth.SAMPLE_RATE

## Voices: partials as [multiple of the note's frequency, amplitude, decay per second].
const VOICES := {
	&"koto": [[1.0, 1.0, 7.0], [2.0, 0.5, 10.0], [3.0, 0.3, 15.0], [4.02, 0.12, 22.0]],
	&"marimba": [[1.0, 1.0, 9.0], [3.98, 0.3, 28.0], [9.9, 0.06, 50.0]],
	&"music_box": [[1.0, 1.0, 5.0], [2.0, 0.35, 7.0], [5.43, 0.16, 12.0]],
	&"synth": [[1.0, 1.0, 6.0], [2.0, 0.5, 8.0], [3.0, 0.33, 10.0], [4.0, 0.25, 12.0]],
	&"bell": [[1.0, 1.0, 3.0], [2.76, 0.4, 5.0], [5.4, 0.18, 8.0]],
	&"bass": [[1.0, 1.0, 5.0], [2.0, 0.3, 7.0]],
	&"synth_bass": [[1.0, 1.0, 6.0], [2.0, 0.5, 8.0], [3.0, 0.3, 10.0]],
}

## Each machine (by fascia name): tempo, key (MIDI note of the tonic), scale (semitones
## above it), the chord roots of the four bars (scale steps), the voices, whether the
## percussion plays off-beats from the start, and the melody's seed.
const STYLES := {
	"classic":
	{
		"bpm": 92.0,
		"tonic": 62,
		"scale": [0, 2, 3, 7, 9],
		"chords": [0, 3, 2, 4],
		"lead": &"koto",
		"bass": &"bass",
		"beat": false,
		"seed": 11,
	},
	"country":
	{
		"bpm": 112.0,
		"tonic": 67,
		"scale": [0, 2, 4, 7, 9],
		"chords": [0, 3, 0, 4],
		"lead": &"marimba",
		"bass": &"bass",
		"beat": false,
		"seed": 23,
	},
	"garden":
	{
		"bpm": 100.0,
		"tonic": 65,
		"scale": [0, 2, 4, 5, 7, 9, 11],
		"chords": [0, 5, 3, 4],
		"lead": &"music_box",
		"bass": &"bass",
		"beat": false,
		"seed": 37,
	},
	"neon":
	{
		"bpm": 120.0,
		"tonic": 57,
		"scale": [0, 2, 3, 5, 7, 8, 10],
		"chords": [0, 5, 2, 6],
		"lead": &"synth",
		"bass": &"synth_bass",
		"beat": true,
		"seed": 41,
	},
	"sakura":
	{
		"bpm": 80.0,
		"tonic": 64,
		"scale": [0, 1, 5, 7, 8],
		"chords": [0, 2, 3, 1],
		"lead": &"bell",
		"bass": &"bass",
		"beat": false,
		"seed": 53,
	},
}


## The machines that have a tune of their own (fascia names); any other gets Classic's.
static func machines() -> PackedStringArray:
	return PackedStringArray(STYLES.keys())


## Seconds one loop of `machine` in `mood` lasts.
static func loop_seconds(machine: String, mood: StringName) -> float:
	return BARS * BEATS_PER_BAR * 60.0 / _bpm(_style(machine), mood)


## The loop of `machine` (a fascia name; unknown: Classic's) in `mood` (MOODS; unknown:
## NORMAL), ready to play: a mono 16-bit AudioStreamWAV that loops forward seamlessly.
static func build(machine: String, mood: StringName) -> AudioStreamWAV:
	return SoundSynth.to_loop(render(machine, mood), 0.8)


## The samples of the loop (see build), one whole loop long.
static func render(machine: String, mood: StringName) -> PackedFloat32Array:
	if not MOODS.has(mood):
		mood = NORMAL
	var style := _style(machine)
	var bpm := _bpm(style, mood)
	var beat := 60.0 / bpm
	var length := roundi(BARS * BEATS_PER_BAR * beat * RATE)
	var out := PackedFloat32Array()
	out.resize(length)
	# a reach a tone up, a jackpot a fourth: brighter as it builds
	var shift := 2 if mood == REACH else (5 if mood == JACKPOT else 0)
	var tonic: int = style["tonic"] + shift
	var scale: Array = style["scale"]
	var chords: Array = style["chords"]
	var notes := {}
	var rng := RandomNumberGenerator.new()
	rng.seed = style["seed"]
	var melody_voice: StringName = style["lead"]
	var bass_voice: StringName = style["bass"]
	for bar in BARS:
		var bar_start := bar * BEATS_PER_BAR * beat
		var root: int = chords[bar]
		var chord := [root, root + 2, root + 4]
		# the melody: mostly chord tones on the beats, passing steps between, a rest or two
		var step_seconds := beat * 0.5
		var last := root + scale.size()
		for step in BEATS_PER_BAR * 2:
			var on_beat := step % 2 == 0
			var roll := rng.randf()
			if not on_beat and roll < 0.35:
				continue
			var degree: int
			if on_beat:
				degree = chord[rng.randi_range(0, 2)] + scale.size()
			else:
				degree = last + (1 if rng.randf() < 0.5 else -1)
			last = degree
			var at := bar_start + step * step_seconds
			var pitch := _midi(tonic, scale, degree)
			_place(out, _note(notes, melody_voice, pitch, RING_SECONDS), at, 0.5)
			if mood == JACKPOT:
				_place(out, _note(notes, &"bell", pitch + 12, RING_SECONDS), at, 0.22)
		# the arpeggio: chord tones in eighths (sixteenths once the reels build up)
		var arp_steps := BEATS_PER_BAR * (2 if mood == NORMAL else 4)
		var arp_seconds := BEATS_PER_BAR * beat / arp_steps
		for step in arp_steps:
			var degree: int = chord[step % 3]
			var pitch := _midi(tonic, scale, degree)
			var level := 0.14 if mood == NORMAL else 0.18
			_place(
				out, _note(notes, melody_voice, pitch, 0.25), bar_start + step * arp_seconds, level
			)
		# the bass: the root on beats 1 and 3, or every eighth when it builds
		var bass_steps := 2 if mood == NORMAL else 8
		for step in bass_steps:
			var pitch := (
				_midi(tonic, scale, root) - 24 + (12 if mood == JACKPOT and step % 2 == 1 else 0)
			)
			var at := bar_start + step * BEATS_PER_BAR * beat / bass_steps
			_place(out, _note(notes, bass_voice, pitch, BASS_SECONDS), at, 0.45)
		_drums(out, notes, style, mood, bar_start, beat)
	if mood == REACH:
		# a rising line over the last bar: the last reel is still turning
		var rise := SoundSynth.sweep(BEATS_PER_BAR * beat, 220.0, 880.0, 0.12, 0.0)
		_place(out, rise, (BARS - 1) * BEATS_PER_BAR * beat, 1.0)
	return out


static func _drums(
	out: PackedFloat32Array,
	notes: Dictionary,
	style: Dictionary,
	mood: StringName,
	bar_start: float,
	beat: float
) -> void:
	var hat: PackedFloat32Array = notes.get(&"hat", PackedFloat32Array())
	if hat.is_empty():
		hat = SoundSynth.noise(0.05, 1.0, 70.0, 0.0, 5)
		notes[&"hat"] = hat
	var kick: PackedFloat32Array = notes.get(&"kick", PackedFloat32Array())
	if kick.is_empty():
		kick = SoundSynth.sweep(0.16, 130.0, 45.0, 1.0, 18.0)
		notes[&"kick"] = kick
	var busy: bool = style["beat"] or mood != NORMAL
	var hats := BEATS_PER_BAR * (4 if mood == REACH else 2)
	for step in hats:
		var off_beat := step % 2 == 1
		if not busy and not off_beat:
			continue
		var level := 0.1 if off_beat else 0.06
		_place(out, hat, bar_start + step * BEATS_PER_BAR * beat / hats, level)
	if mood == JACKPOT or style["beat"]:
		for step in BEATS_PER_BAR:
			_place(out, kick, bar_start + step * beat, 0.5)


# Adds `clip` times `gain` into `out` from `at_seconds`, wrapping round the loop's end so a
# note ringing past it sounds at the start (the loop stays seamless).
static func _place(
	out: PackedFloat32Array, clip: PackedFloat32Array, at_seconds: float, gain: float
) -> void:
	var length := out.size()
	var start := int(at_seconds * RATE) % length
	for i in clip.size():
		var k := start + i
		if k >= length:
			k -= length
		out[k] += clip[i] * gain


# The note of MIDI pitch `pitch` in `voice`, `seconds` long: rendered once per build, since
# a tune repeats few distinct notes many times.
static func _note(
	cache: Dictionary, voice: StringName, pitch: int, seconds: float
) -> PackedFloat32Array:
	var key := "%s:%d:%.2f" % [voice, pitch, seconds]
	if cache.has(key):
		return cache[key]
	var frequency := 440.0 * pow(2.0, (pitch - 69) / 12.0)
	var parts: Array[PackedFloat32Array] = []
	for partial: Array in VOICES.get(voice, VOICES[&"koto"]):
		var hz: float = frequency * partial[0]
		if hz < RATE * 0.45:
			parts.append(PackedFloat32Array([hz, partial[1], partial[2]]))
	var clip := SoundSynth.partials(seconds, parts)
	# a short fade at the end: a note cut while it still rings would click
	var fade := mini(clip.size(), int(0.02 * RATE))
	for i in fade:
		clip[clip.size() - 1 - i] *= float(i) / fade
	cache[key] = clip
	return clip


# MIDI pitch of scale step `degree` (steps past the scale's end climb octaves).
static func _midi(tonic: int, scale: Array, degree: int) -> int:
	var size := scale.size()
	var octave := floori(float(degree) / size)
	var step: int = scale[degree - octave * size]
	return tonic + octave * 12 + step


static func _style(machine: String) -> Dictionary:
	return STYLES.get(machine, STYLES["classic"])


static func _bpm(style: Dictionary, mood: StringName) -> float:
	var bpm: float = style["bpm"]
	match mood:
		REACH:
			return bpm * 1.15
		JACKPOT:
			return bpm * 1.25
	return bpm
