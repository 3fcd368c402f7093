class_name RailExitTable
extends RefCounted
## Where each shot power leaves the launch rail. With no other ball in the way, every shot
## of one power climbs the rail the same way, so the climb is simulated once per power
## level (AnalysisPlan.POWER_STEP) and the analysis starts each shot's ball where and when
## it leaves the rail, in free flight: same position, same velocity, no contact held. That
## saves about a third of the work. A shot too weak to clear the rail is recorded as rolled
## back; a power whose climb never settles into free flight is simulated in full instead.
##
## The climb runs in the board's own world, many powers at once with ball contacts off.

## What a power level's climb ended as.
enum Fate { UNKNOWN, EXIT, RETURNED, FULL }

## Powers climbed side by side in one world (a fixed grouping: the same table for any
## thread count).
const GROUP_LEVELS := 64
## The hand-over waits until the ball is this far past the rail's end (degrees round the
## ring), over the deflector and into the field.
const EXIT_MARGIN_DEG := 1.0
## A velocity that changed by gravity alone (within this, px/s) means free flight.
const FREE_FLIGHT_EPS := 1e-3
## Longest climb followed, seconds.
const MAX_SECONDS := 8.0

## Per power level: a Fate, and for EXIT the hand-over state and the steps it took.
var fate := PackedByteArray()
var exit_pos := PackedVector2Array()
var exit_vel := PackedVector2Array()
var exit_steps := PackedInt32Array()
## Per power level: density cells the ball passed on the rail (sampled every
## PachinkoShotChunk.SAMPLE_EVERY steps), and steps simulated (RETURNED: the whole flight).
var samples: Array[PackedInt32Array] = []
var steps := PackedInt32Array()
## Per power level: the x of the first pin the ball met (NAN: it met none). With no other
## ball in the way every shot of one power meets the same first pin.
var entry_x := PackedFloat32Array()
## True when each EXIT climb was followed on past the hand-over to its first pin (a played
## run needs that: its shots meet other balls). False: an EXIT climb stops at the hand-over,
## and where the ball had met no pin by then entry_x is NAN and the contact-free chunk, whose
## ball flies on from the same state, records the first pin as its shot meets it (the
## part past the hand-over was about half the climbs' ball-steps).
var to_first_pin := true


func _init() -> void:
	var n := AnalysisPlan.level_count()
	fate.resize(n)
	exit_pos.resize(n)
	exit_vel.resize(n)
	exit_steps.resize(n)
	steps.resize(n)
	samples.resize(n)
	entry_x.resize(n)
	entry_x.fill(NAN)


## The groups (lists of power levels) to climb for the levels `needed` marks (1 = needed).
static func groups_for(needed: PackedByteArray) -> Array[PackedInt32Array]:
	var groups: Array[PackedInt32Array] = []
	var current := PackedInt32Array()
	for q in needed.size():
		if needed[q] == 0:
			continue
		current.append(q)
		if current.size() == GROUP_LEVELS:
			groups.append(current)
			current = PackedInt32Array()
	if not current.is_empty():
		groups.append(current)
	return groups


## True when the shots of power level `q` must record their own first pin (see
## to_first_pin): the climb handed the ball over before it met one.
func entry_after_exit(q: int) -> bool:
	return not to_first_pin and fate[q] == Fate.EXIT and is_nan(entry_x[q])


## Copies a climbed group's results (from RailClimber.climb_group) into the table.
func store(part: RailExitTable, levels: PackedInt32Array) -> void:
	for q in levels:
		fate[q] = part.fate[q]
		exit_pos[q] = part.exit_pos[q]
		exit_vel[q] = part.exit_vel[q]
		exit_steps[q] = part.exit_steps[q]
		steps[q] = part.steps[q]
		samples[q] = part.samples[q]
		entry_x[q] = part.entry_x[q]
