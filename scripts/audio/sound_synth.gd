class_name SoundSynth
extends RefCounted
## Small synthesiser for the sound bank: builds mono 16-bit AudioStreamWAV clips from
## decaying partials and filtered noise, so every sound in the game is made by code.

const SAMPLE_RATE := 22050


## A clip of `seconds` built from `partials`: each entry is [frequency Hz, amplitude,
## decay per second, start offset s]. Partials ring out exponentially (a struck object).
static func partials(seconds: float, parts: Array[PackedFloat32Array]) -> PackedFloat32Array:
	var count := int(seconds * SAMPLE_RATE)
	var out := PackedFloat32Array()
	out.resize(count)
	for part in parts:
		var freq := part[0]
		var amp := part[1]
		var decay := part[2]
		var start := int(part[3] * SAMPLE_RATE) if part.size() > 3 else 0
		# A rotating phasor and a per-sample decay factor: only multiplications per
		# sample (sin and exp per sample made the long bells slow to build).
		var step := TAU * freq / SAMPLE_RATE
		var rot_c := cos(step)
		var rot_s := sin(step)
		var fall := exp(-decay / SAMPLE_RATE)
		var c := 1.0
		var sn := 0.0
		var env := amp
		# A 2 ms ramp keeps the onset from clicking; a whole number of samples (44).
		@warning_ignore("integer_division")
		var attack_len := SAMPLE_RATE / 500
		for i in range(start, count):
			var k := i - start
			var attack := minf(1.0, float(k) / float(attack_len))
			out[i] += env * attack * sn
			var nc := c * rot_c - sn * rot_s
			sn = c * rot_s + sn * rot_c
			c = nc
			env *= fall
	return out


## A pitch sweep from `from_hz` to `to_hz` with an exponential decay (whooshes, slides).
static func sweep(
	seconds: float, from_hz: float, to_hz: float, amp: float, decay: float
) -> PackedFloat32Array:
	var count := int(seconds * SAMPLE_RATE)
	var out := PackedFloat32Array()
	out.resize(count)
	var phase := 0.0
	for i in count:
		var t := float(i) / SAMPLE_RATE
		var freq := lerpf(from_hz, to_hz, t / seconds)
		phase += TAU * freq / SAMPLE_RATE
		var attack := minf(1.0, t * 400.0)
		out[i] = amp * attack * exp(-decay * t) * sin(phase)
	return out


## Low-passed white noise with an exponential decay; `smooth` in 0..1 (higher = darker).
static func noise(
	seconds: float, amp: float, decay: float, smooth: float, seed_value: int
) -> PackedFloat32Array:
	var rng := RandomNumberGenerator.new()
	rng.seed = seed_value
	var count := int(seconds * SAMPLE_RATE)
	var out := PackedFloat32Array()
	out.resize(count)
	var last := 0.0
	for i in count:
		var t := float(i) / SAMPLE_RATE
		last = lerpf(rng.randf_range(-1.0, 1.0), last, smooth)
		out[i] = amp * exp(-decay * t) * last
	return out


## Sums clips sample by sample into a clip as long as the longest.
static func mix(clips: Array[PackedFloat32Array]) -> PackedFloat32Array:
	var length := 0
	for clip in clips:
		length = maxi(length, clip.size())
	var out := PackedFloat32Array()
	out.resize(length)
	for clip in clips:
		for i in clip.size():
			out[i] += clip[i]
	return out


## Places `clip` into `target` starting at `at_seconds` (adds; grows `target` as needed).
static func overlay(
	target: PackedFloat32Array, clip: PackedFloat32Array, at_seconds: float
) -> void:
	var start := int(at_seconds * SAMPLE_RATE)
	if target.size() < start + clip.size():
		target.resize(start + clip.size())
	for i in clip.size():
		target[start + i] += clip[i]


## Converts float samples to a 16-bit mono AudioStreamWAV, normalising to `peak` (0..1)
## and fading the last 5 ms so clips never end on a click.
static func to_stream(samples: PackedFloat32Array, peak: float = 0.9) -> AudioStreamWAV:
	var loudest := 0.0001
	for s in samples:
		loudest = maxf(loudest, absf(s))
	var gain := peak / loudest
	var fade := mini(samples.size(), int(0.005 * SAMPLE_RATE))
	var data := PackedByteArray()
	data.resize(samples.size() * 2)
	for i in samples.size():
		var tail := 1.0
		if i >= samples.size() - fade:
			tail = float(samples.size() - 1 - i) / float(maxi(fade, 1))
		var value := clampi(int(samples[i] * gain * tail * 32767.0), -32768, 32767)
		data.encode_s16(i * 2, value)
	var stream := AudioStreamWAV.new()
	stream.format = AudioStreamWAV.FORMAT_16_BITS
	stream.mix_rate = SAMPLE_RATE
	stream.stereo = false
	stream.data = data
	return stream


## Like `to_stream`, but the clip loops forever from its first sample to its last, with no
## fade at the seam (the samples should already run smoothly from their end into their start).
static func to_loop(samples: PackedFloat32Array, peak: float = 0.9) -> AudioStreamWAV:
	# to_stream fades its last 5 ms: give it a copy of the start to fade that is never played
	var padded := samples.duplicate()
	var pad := mini(samples.size(), int(0.01 * SAMPLE_RATE))
	padded.append_array(samples.slice(0, pad))
	var stream := to_stream(padded, peak)
	stream.loop_mode = AudioStreamWAV.LOOP_FORWARD
	stream.loop_begin = 0
	stream.loop_end = samples.size()
	return stream
