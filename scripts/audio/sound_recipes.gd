class_name SoundRecipes
extends RefCounted
## The game's sound effects as recipes for the synthesiser. Every name here is a sound the
## SoundBank can play; both games share them (pins and pockets for pachinko, walls, goal
## and holes for the maze).

## Sound names, so callers never spell a string twice.
const PIN_TICK := &"pin_tick"
const LAUNCH := &"launch"
const POCKET_WIN := &"pocket_win"
const DRAIN := &"drain"
const BALL_RETURN := &"ball_return"
const GAME_OVER := &"game_over"
const WALL_THUD := &"wall_thud"
const GOAL_CHIME := &"goal_chime"
const HOLE_FALL := &"hole_fall"
const FANFARE := &"fanfare"
const UI_CLICK := &"ui_click"
## A maze ball rolling on the board: a seamless loop, pitched and faded by its speed.
const BALL_ROLL := &"ball_roll"
## A maze ball dropping into a hole: a knock on the rim, then a hollow thud below.
const BALL_DROP := &"ball_drop"
## Length of the rolling loop, in seconds.
const ROLL_LOOP_SECONDS := 1.0
## The bonus layer: a reel landing, the jackpot, a tulip opening, the start pocket's catch.
const REEL_STOP := &"reel_stop"
const JACKPOT := &"jackpot"
const TULIP_OPEN := &"tulip_open"
const START_CATCH := &"start_catch"
## The fever round ending (the last attacker's lid shuts): a falling two-note sigh.
const FEVER_END := &"fever_end"


## Every recipe name, in a stable order (the juice and then the jackpot recipes last).
static func names() -> Array[StringName]:
	var all: Array[StringName] = [
		PIN_TICK,
		LAUNCH,
		POCKET_WIN,
		DRAIN,
		BALL_RETURN,
		GAME_OVER,
		WALL_THUD,
		GOAL_CHIME,
		HOLE_FALL,
		FANFARE,
		UI_CLICK,
		BALL_ROLL,
		BALL_DROP,
		REEL_STOP,
		JACKPOT,
		TULIP_OPEN,
		START_CATCH,
		FEVER_END,
	]
	all.append_array(JuiceRecipes.names())
	all.append_array(JackpotRecipes.names())
	all.append_array(GoldRecipes.names())
	return all


## Builds the named clip; null (with an error naming it) for an unknown name.
static func build(sound: StringName) -> AudioStreamWAV:
	match sound:
		PIN_TICK:
			return SoundSynth.to_stream(_pin_tick(), 0.8)
		LAUNCH:
			return SoundSynth.to_stream(_launch(), 0.85)
		POCKET_WIN:
			return SoundSynth.to_stream(
				_arpeggio([784.0, 988.0, 1175.0, 1568.0, 1976.0], 0.07), 0.8
			)
		DRAIN:
			return SoundSynth.to_stream(_drain(), 0.7)
		BALL_RETURN:
			return SoundSynth.to_stream(_ball_return(), 0.6)
		GAME_OVER:
			return SoundSynth.to_stream(_arpeggio([659.0, 523.0, 440.0, 330.0], 0.16), 0.7)
		WALL_THUD:
			return SoundSynth.to_stream(_wall_thud(), 0.8)
		GOAL_CHIME:
			return SoundSynth.to_stream(_arpeggio([1047.0, 1568.0], 0.09), 0.75)
		HOLE_FALL:
			return SoundSynth.to_stream(SoundSynth.sweep(0.45, 620.0, 90.0, 0.8, 4.0), 0.7)
		FANFARE:
			return SoundSynth.to_stream(
				_arpeggio([523.0, 659.0, 784.0, 1047.0, 1319.0, 1568.0], 0.1), 0.8
			)
		UI_CLICK:
			return SoundSynth.to_stream(SoundSynth.partials(0.05, [_p(2400.0, 1.0, 90.0)]), 0.5)
		BALL_ROLL:
			return SoundSynth.to_loop(_ball_roll(), 0.8)
		BALL_DROP:
			return SoundSynth.to_stream(_ball_drop(), 0.85)
		REEL_STOP:
			return SoundSynth.to_stream(_reel_stop(), 0.7)
		JACKPOT:
			var notes: Array[float] = [523.0, 659.0, 784.0, 1047.0, 784.0, 1047.0, 1319.0, 1568.0]
			return SoundSynth.to_stream(_arpeggio(notes, 0.085), 0.85)
		TULIP_OPEN:
			return SoundSynth.to_stream(SoundSynth.sweep(0.16, 520.0, 1180.0, 0.6, 14.0), 0.6)
		START_CATCH:
			return SoundSynth.to_stream(_arpeggio([1319.0, 1760.0], 0.05), 0.7)
		FEVER_END:
			return SoundSynth.to_stream(_arpeggio([1047.0, 784.0, 523.0], 0.12), 0.7)
	if JuiceRecipes.has(sound):
		return JuiceRecipes.build(sound)
	if JackpotRecipes.has(sound):
		return JackpotRecipes.build(sound)
	if GoldRecipes.has(sound):
		return GoldRecipes.build(sound)
	push_error("SoundRecipes: no recipe for sound '%s'" % sound)
	return null


## Steel ball on a brass pin: a bright, inharmonic ping that dies in ~60 ms.
static func _pin_tick() -> PackedFloat32Array:
	var ring := (
		SoundSynth
		. partials(
			0.09,
			[_p(3150.0, 1.0, 55.0), _p(4710.0, 0.55, 70.0), _p(6980.0, 0.3, 95.0)],
		)
	)
	var click := SoundSynth.noise(0.01, 0.5, 400.0, 0.1, 7)
	return SoundSynth.mix([ring, click])


## The spring flipper: a noisy thwack and a low rising whoosh as the ball leaves.
static func _launch() -> PackedFloat32Array:
	var thwack := SoundSynth.noise(0.06, 1.0, 70.0, 0.55, 11)
	var body := SoundSynth.partials(0.12, [_p(180.0, 0.8, 30.0), _p(410.0, 0.4, 45.0)])
	var whoosh := SoundSynth.noise(0.32, 0.35, 9.0, 0.92, 12)
	var rise := SoundSynth.sweep(0.3, 220.0, 520.0, 0.25, 8.0)
	var out := SoundSynth.mix([thwack, body])
	SoundSynth.overlay(out, SoundSynth.mix([whoosh, rise]), 0.03)
	return out


## Bell notes one after another, each a struck tone with a soft octave shimmer.
static func _arpeggio(notes: Array[float], gap: float) -> PackedFloat32Array:
	var out := PackedFloat32Array()
	for i in notes.size():
		var f: float = notes[i]
		var bell := SoundSynth.partials(
			0.5, [_p(f, 1.0, 6.0), _p(f * 2.0, 0.35, 9.0), _p(f * 3.01, 0.12, 14.0)]
		)
		SoundSynth.overlay(out, bell, gap * i)
	return out


## A ball swallowed by the gutter: a falling tone over a dull knock.
static func _drain() -> PackedFloat32Array:
	var slide := SoundSynth.sweep(0.35, 440.0, 110.0, 0.6, 6.0)
	var knock := SoundSynth.partials(0.2, [_p(95.0, 1.0, 18.0), _p(190.0, 0.3, 25.0)])
	return SoundSynth.mix([slide, knock])


## A weak shot rolling back to the cup: two soft clacks.
static func _ball_return() -> PackedFloat32Array:
	var clack := SoundSynth.partials(0.08, [_p(1200.0, 0.8, 60.0), _p(2300.0, 0.3, 80.0)])
	var out := clack.duplicate()
	SoundSynth.overlay(out, clack, 0.09)
	return out


## A maze ball against a wall: low, woody and short.
static func _wall_thud() -> PackedFloat32Array:
	var knock := SoundSynth.partials(0.12, [_p(140.0, 1.0, 35.0), _p(330.0, 0.45, 50.0)])
	var tap := SoundSynth.noise(0.03, 0.4, 150.0, 0.7, 21)
	return SoundSynth.mix([knock, tap])


## A ball rolling on wood: dark rumbling noise with a faint grain that flutters, made one
## loop long with its end cross-faded into its start so the loop has no seam.
static func _ball_roll() -> PackedFloat32Array:
	var length := int(ROLL_LOOP_SECONDS * SoundSynth.SAMPLE_RATE)
	var seam := int(0.15 * SoundSynth.SAMPLE_RATE)
	var rumble := SoundSynth.noise(ROLL_LOOP_SECONDS + 0.15, 1.0, 0.0, 0.985, 31)
	var grain := SoundSynth.noise(ROLL_LOOP_SECONDS + 0.15, 0.25, 0.0, 0.6, 32)
	var out := PackedFloat32Array()
	out.resize(length)
	for i in length:
		out[i] = rumble[i] + grain[i] * _flutter(i)
	for i in seam:
		var k := float(i) / float(seam)
		var tail := rumble[length + i] + grain[length + i] * _flutter(length + i)
		out[i] = lerpf(tail, out[i], k)
	return out


# The grain's flutter: 23 whole cycles a second, so it too runs on across the loop's seam.
static func _flutter(sample: int) -> float:
	return 0.75 + 0.25 * sin(TAU * 23.0 * float(sample) / SoundSynth.SAMPLE_RATE)


## A ball lost into a hole: a bright knock on the rim, a hollow low thud at the bottom,
## and a small rattle as it settles.
static func _ball_drop() -> PackedFloat32Array:
	var rim := SoundSynth.partials(0.08, [_p(900.0, 0.6, 60.0), _p(1750.0, 0.3, 80.0)])
	var thud := SoundSynth.partials(0.3, [_p(105.0, 1.0, 14.0), _p(212.0, 0.45, 20.0)])
	var rattle := SoundSynth.partials(0.1, [_p(620.0, 0.35, 45.0)])
	var out := rim.duplicate()
	SoundSynth.overlay(out, SoundSynth.noise(0.05, 0.3, 60.0, 0.5, 33), 0.0)
	SoundSynth.overlay(out, thud, 0.16)
	SoundSynth.overlay(out, rattle, 0.3)
	SoundSynth.overlay(out, rattle, 0.37)
	return out


## A reel landing on its symbol: a short knock under a small bell.
static func _reel_stop() -> PackedFloat32Array:
	var knock := SoundSynth.partials(0.08, [_p(220.0, 1.0, 45.0), _p(520.0, 0.4, 60.0)])
	var bell := SoundSynth.partials(0.2, [_p(1568.0, 0.5, 18.0), _p(2350.0, 0.2, 25.0)])
	return SoundSynth.mix([knock, bell])


static func _p(freq: float, amp: float, decay: float) -> PackedFloat32Array:
	return PackedFloat32Array([freq, amp, decay])
