extends RefCounted
## What this machine gives a second GDScript thread right now: a piece of work timed on one
## thread, then two such pieces at once on two threads, sharing nothing; the scaling is
## 2 × one / both (2.0: the second core is as fast as the first). round_scaling() times a
## loop free of calls and of shared writes (float math over a packed array each thread only
## reads); pair_scaling() any two pieces, such as two copies of the GDScript floor or two
## whole worlds (see OursRunner.thread_scaling). On the shared machines this project is
## measured on, it moved between about 1.0 and 2.0 from one ten minutes to the next, so S1's
## thread_scaling is read against these, measured in the same rounds.

## Loop iterations per thread and run: some 10-20 ms.
const WORK := 400000


## One round of the call-free loop: returns 2 × (one thread alone) / (two threads at once).
static func round_scaling() -> float:
	var first := Loop.new()
	var second := Loop.new()
	return pair_scaling(first.run, second.run)


## Times `first` alone on this thread, then `first` here and `second` (the same work) on a
## new thread at once; returns 2 × alone / both. The two may be one callable when it
## writes nothing shared.
static func pair_scaling(first: Callable, second: Callable) -> float:
	var t0: int = Time.get_ticks_usec()
	first.call()
	var one: int = Time.get_ticks_usec() - t0
	var thread := Thread.new()
	t0 = Time.get_ticks_usec()
	thread.start(second)
	first.call()
	thread.wait_to_finish()
	var both: int = Time.get_ticks_usec() - t0
	return 2.0 * one / maxf(both, 1.0)


## The loop each thread runs (on its own values: no line is written by both threads).
class Loop:
	extends RefCounted
	## Read-only inputs.
	var values := PackedFloat32Array()
	## The sum, kept so the loop's work is used.
	var result := 0.0

	func _init() -> void:
		values.resize(1024)
		for k: int in values.size():
			values[k] = float(k) * 0.001

	## Runs WORK iterations.
	func run() -> void:
		var v := Vector2(1.0, 2.0)
		var acc := 0.0
		for i: int in WORK:
			v = v * 0.999 + Vector2(values[i & 1023], 0.002)
			acc += v.length_squared()
		result = acc
