class_name Gates
extends RefCounted
## The gates of a BallWorld: sets of petals (capsules hinged at one end, a tulip's wings)
## that swing between a shut pose and an open pose, on command (set_open) or on their own
## schedule (set_schedule). Internal to scripts/physics: use BallWorld.add_gate().
##
## Each petal is a driven one-blade rotor in the world's Windmills store, so it is binned,
## substepped and touched exactly as a windmill blade is: contacts see its surface speed
## (a closing petal throws a ball) and no ball passes through it. Gates only drive those
## rotors: at the start of each step a gate's openness (0 shut, 1 open) moves toward its
## target by the step's share of its swing, and each petal turns at the one constant speed
## that takes it from this step's pose to the next (held so that no tip outruns the top
## speed, which BallMover's swept test relies on); at the end of the step the pose is set
## to exactly the new openness. Everything follows from the state at the step's start, so
## any thread count gives the same result.

## Per petal: its rotor in the Windmills store, its gate, and its angle shut and open
## (radians, y down: -PI / 2 points straight up).
var petal_rotor := PackedInt32Array()
var petal_gate := PackedInt32Array()
var shut_angle := PackedFloat64Array()
var open_angle := PackedFloat64Array()
## Per gate: how open it is at the step's start (0 shut .. 1 open), where it is heading
## (1 open, 0 shut), and the seconds a whole swing takes.
var openness := PackedFloat64Array()
var target := PackedByteArray()
var swing_seconds := PackedFloat64Array()
## Per gate: its schedule (seconds open, seconds shut; 0 and 0 for none) and the seconds
## spent so far in the scheduled phase under way.
var open_seconds := PackedFloat64Array()
var shut_seconds := PackedFloat64Array()
var phase_time := PackedFloat64Array()
## Per gate: its openness at the end of the step under way (set by begin_step).
var _next := PackedFloat64Array()


func count() -> int:
	return openness.size()


func petal_count() -> int:
	return petal_rotor.size()


## Adds a shut gate whose petals take `seconds` to swing fully open or shut; returns its
## index, or -1 with an error for a swing time that is not finite and > 0.
func add(seconds: float) -> int:
	if not is_finite(seconds) or seconds <= 0.0:
		push_error("BallWorld.add_gate: the swing time must be finite and > 0 (got %s)" % seconds)
		return -1
	openness.append(0.0)
	target.append(0)
	swing_seconds.append(seconds)
	open_seconds.append(0.0)
	shut_seconds.append(0.0)
	phase_time.append(0.0)
	_next.append(0.0)
	return openness.size() - 1


## Adds petal `rotor` (already in `wheels`) to `gate`, shut at `shut` and open at `open`
## radians; poses it as the gate is now. Returns the petal's index.
func add_petal(wheels: Windmills, gate: int, rotor: int, shut: float, open: float) -> int:
	petal_rotor.append(rotor)
	petal_gate.append(gate)
	shut_angle.append(shut)
	open_angle.append(open)
	var petal: int = petal_rotor.size() - 1
	wheels.angle[rotor] = pose(petal, openness[gate])
	return petal


## The angle of `petal` when its gate is `amount` open.
func pose(petal: int, amount: float) -> float:
	return lerpf(shut_angle[petal], open_angle[petal], amount)


## Sends `gate` open or shut; `at_once` puts it there now instead of swinging.
func set_open(wheels: Windmills, gate: int, open: bool, at_once: bool) -> void:
	target[gate] = 1 if open else 0
	if not at_once:
		return
	openness[gate] = 1.0 if open else 0.0
	for petal: int in petal_rotor.size():
		if petal_gate[petal] == gate:
			wheels.angle[petal_rotor[petal]] = pose(petal, openness[gate])
			wheels.omega[petal_rotor[petal]] = 0.0


## Gives `gate` a schedule: open for `open_for` s, then shut for `shut_for` s, over and
## over, starting from the phase its target is in now; 0 and 0 ends the schedule.
func set_schedule(gate: int, open_for: float, shut_for: float) -> void:
	open_seconds[gate] = open_for
	shut_seconds[gate] = shut_for
	phase_time[gate] = 0.0


## Starts a step of `dt` s: runs the schedules, moves each gate's openness toward its target
## for the step, and sets each petal's rotor to this step's pose and the constant turn
## that reaches the next (a tip never faster than `max_tip_speed`).
func begin_step(wheels: Windmills, dt: float, max_tip_speed: float) -> void:
	for g: int in openness.size():
		_run_schedule(g, dt)
		# A hair more than the step's share, so rounding never leaves a sliver of swing
		# for one more step (a 0.2 s swing takes 24 steps at 120 Hz, not 25).
		var most: float = dt / swing_seconds[g] * (1.0 + 1e-9)
		_next[g] = move_toward(openness[g], float(target[g]), most)
	# A petal's tip may not outrun the top speed: the whole gate then swings slower.
	for petal: int in petal_rotor.size():
		var g: int = petal_gate[petal]
		var swing: float = absf(open_angle[petal] - shut_angle[petal])
		var most_turn: float = max_tip_speed * dt / wheels.reach[petal_rotor[petal]]
		if swing * absf(_next[g] - openness[g]) > most_turn:
			_next[g] = move_toward(openness[g], _next[g], most_turn / swing)
	for petal: int in petal_rotor.size():
		var g: int = petal_gate[petal]
		var rotor: int = petal_rotor[petal]
		var from: float = pose(petal, openness[g])
		wheels.angle[rotor] = from
		wheels.omega[rotor] = (pose(petal, _next[g]) - from) / dt


## Ends the step: each gate is at its new openness, each petal exactly at its pose there.
func end_step(wheels: Windmills) -> void:
	for g: int in openness.size():
		openness[g] = _next[g]
	for petal: int in petal_rotor.size():
		var rotor: int = petal_rotor[petal]
		wheels.angle[rotor] = pose(petal, openness[petal_gate[petal]])
		wheels.omega[rotor] = 0.0


# A scheduled gate turns round when its phase is over (time counted per step, so the same
# steps give the same schedule).
func _run_schedule(g: int, dt: float) -> void:
	if open_seconds[g] <= 0.0 and shut_seconds[g] <= 0.0:
		return
	phase_time[g] += dt
	var phase: float = open_seconds[g] if target[g] != 0 else shut_seconds[g]
	if phase_time[g] >= phase:
		phase_time[g] -= phase
		target[g] = 0 if target[g] != 0 else 1
