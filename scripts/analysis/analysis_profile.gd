class_name AnalysisProfile
extends RefCounted
## Where a pachinko analysis spends its time, stage by stage (`--analyze ... --profile`,
## the bench): wall microseconds per stage, summed over every chunk and climb group (so with
## several threads the stages add up to more than the wall time). Off unless asked for: the
## analysis then keeps no profile and its loops skip the clock.
##
## One profile per chunk or climb group, filled on its own thread and added into the
## analysis's in order (add()), so no lock is held while a chunk runs.

## The stages: the launch table (LaunchCalibration, measured once per rail shape and cached),
## the rail climbs (RailClimber: world set-up and stepping), a chunk's set-up (its world and
## ledger), its shots fired (spawns and the rail table's samples), the world's steps, the
## density samples, the hopeless-ball test, the stuck-ball check, and the merge of the
## chunk tallies.
enum Stage { LAUNCH_TABLE, CLIMB, CHUNK_SETUP, FIRE, STEP, SAMPLE, HOPELESS, CHECK, MERGE }

## Names of the stages, as to_dict() reports them.
const NAMES: Array[String] = [
	"launch_table", "climb", "chunk_setup", "fire", "step", "sample", "hopeless", "check", "merge"
]

## Microseconds per stage (indexed by Stage).
var usec := PackedInt64Array()
## Climb groups and chunks run, world steps taken by the climbs and by the chunks, and
## ball-steps simulated by the climbs (the chunks' are the tally's ball_steps).
var climb_groups := 0
var climb_steps := 0
var climb_ball_steps := 0
var chunks := 0
var chunk_steps := 0


func _init() -> void:
	usec.resize(NAMES.size())


## Adds `elapsed` microseconds to `stage`.
func add_usec(stage: Stage, elapsed: int) -> void:
	usec[stage] += elapsed


## Adds another profile's times and counts to this one.
func add(other: AnalysisProfile) -> void:
	for s in usec.size():
		usec[s] += other.usec[s]
	climb_groups += other.climb_groups
	climb_steps += other.climb_steps
	climb_ball_steps += other.climb_ball_steps
	chunks += other.chunks
	chunk_steps += other.chunk_steps


## Total microseconds over every stage.
func total_usec() -> int:
	var t := 0
	for u in usec:
		t += u
	return t


## The profile as plain data: seconds per stage (3 decimals), the counts, and each stage's
## share of the stages' total.
func to_dict() -> Dictionary:
	var seconds := {}
	var share := {}
	var total := maxf(total_usec(), 1.0)
	for s in NAMES.size():
		seconds[NAMES[s]] = snappedf(usec[s] / 1e6, 0.001)
		share[NAMES[s]] = snappedf(usec[s] / total, 0.001)
	return {
		"seconds": seconds,
		"share": share,
		"climb_groups": climb_groups,
		"climb_steps": climb_steps,
		"climb_ball_steps": climb_ball_steps,
		"chunks": chunks,
		"chunk_steps": chunk_steps,
	}
