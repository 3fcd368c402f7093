class_name BoardRanges
extends RefCounted
## The allowed range of a board's tuning and bonus numbers: one table that both the file
## reader (board_schema.gd) and the validator (BoardValidator, BonusChecks) check against, so
## a value the editor or a generator accepts is never refused when the file is read back.

## Tuning fields: name → [min, max]; the fields themselves are PhysicsTuning's properties.
## A vector's range applies to each of its parts.
const TUNING := {
	"gravity": [-100000.0, 100000.0],
	"restitution": [0.0, 1.0],
	"wall_restitution": [0.0, 1.0],
	"ball_restitution": [0.0, 1.0],
	"tangent_friction": [0.0, 1.0],
	"rolling_friction": [0.0, 100000.0],
	"tilt_gravity": [0.0, 1000000.0],
	"max_speed": [1.0, 100000.0],
	"min_horizontal_speed": [0.0, 10000.0],
	"fixed_hz": [30.0, 1000.0],
	"bounce_threshold": [0.0, 10000.0],
	"rest_speed": [0.0, 10000.0],
	"sleep_time": [0.0, 60.0],
	"drain_slide_time": [0.0, 60.0],
	"x_cap_friction_time": [0.0, 1.0],
	"speed_cap": [0, 1],  # PhysicsTuning.SpeedCap
	"friction_against": [0, 1],  # PhysicsTuning.FrictionAgainst
	"wall_cap_contact": [0, 1],  # PhysicsTuning.CapContact
}
## Tuning fields written only when they are not 0: added after boards were shipped, so every
## board that leaves them off keeps its text (and its content hash, which replays check).
const TUNING_WRITTEN_WHEN_SET: Array[String] = ["x_cap_friction_time"]
## A tuning field with no range of its own above gets this one.
const TUNING_DEFAULT := [-1000000.0, 1000000.0]
## Bonus pockets (BonusPocketSpec): balls paid per catch, symbols per reel (start pockets),
## seconds and catches an attacker stays open.
const BONUS_PAYOUT := [0, 100]
const BONUS_SYMBOLS := [2, 9]
const BONUS_OPEN_SECONDS := [1.0, 30.0]
const BONUS_OPEN_CATCHES := [1, 50]


## The tuning fields a board may set: PhysicsTuning's stored number and vector properties,
## name → [Variant.Type, min, max].
static func tuning_fields() -> Dictionary:
	var fields := {}
	for prop in PhysicsTuning.new().get_property_list():
		var usage: int = prop["usage"]
		var type: int = prop["type"]
		if usage & PROPERTY_USAGE_STORAGE == 0:
			continue
		if type != TYPE_FLOAT and type != TYPE_INT and type != TYPE_VECTOR2:
			continue
		var name: String = prop["name"]
		var limits: Array = TUNING.get(name, TUNING_DEFAULT)
		fields[name] = [type, limits[0], limits[1]]
	return fields
