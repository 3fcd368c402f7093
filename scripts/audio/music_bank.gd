class_name MusicBank
extends RefCounted
## The machines' music loops (music_recipes.gd), built on a worker thread the first time a
## machine is asked for and kept for the rest of the run: about 0.5 s of synthesis per mood,
## never on the main thread and never per frame. `request` starts the build (the normal
## mood first, so it can start playing while the others are made); `loop` answers the stream
## once it is ready, null until then.

# "machine:mood" -> the built loop. Shared with the workers: every read and write holds it.
static var _loops: Dictionary[String, AudioStreamWAV] = {}
static var _lock := Mutex.new()
# machine -> its worker task id, for every machine requested so far
static var _tasks: Dictionary[String, int] = {}


## Starts building every mood of `machine` (a fascia name) on a worker, unless it was
## asked for before.
static func request(machine: String) -> void:
	if _tasks.has(machine):
		return
	_tasks[machine] = WorkerThreadPool.add_task(
		_build_all.bind(machine), false, "MusicBank %s" % machine
	)


## True once `request(machine)` has been called this run.
static func is_requested(machine: String) -> bool:
	return _tasks.has(machine)


## The loop of `machine` in `mood`, or null while it is still being built (or was never
## requested).
static func loop(machine: String, mood: StringName) -> AudioStreamWAV:
	_lock.lock()
	var found: AudioStreamWAV = _loops.get(_key(machine, mood))
	_lock.unlock()
	return found


## Waits for every build started (the game calls it as it quits; tests to read the loops).
static func wait_for_background() -> void:
	for machine: String in _tasks:
		var task := _tasks[machine]
		if task >= 0:
			WorkerThreadPool.wait_for_task_completion(task)
			_tasks[machine] = -1


static func _build_all(machine: String) -> void:
	for mood in MusicRecipes.MOODS:
		var built := MusicRecipes.build(machine, mood)
		_lock.lock()
		_loops[_key(machine, mood)] = built
		_lock.unlock()


static func _key(machine: String, mood: StringName) -> String:
	return "%s:%s" % [machine, mood]
