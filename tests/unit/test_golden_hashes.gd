extends GutTest
## Golden state hashes (issue 43): every golden run (tests/golden/golden_runs.gd: the bench
## scenes on 1 and 2 threads, every shipped board's autoplay, a replay of each game) still
## gives the hash tests/golden/golden_hashes.json holds. A run that moved while the physics
## and rules versions stayed is a change nobody meant: it is named, with what to do.

const GoldenRuns := preload("res://tests/golden/golden_runs.gd")

var _table: Dictionary


func before_all() -> void:
	var text := FileAccess.get_file_as_string(GoldenRuns.TABLE_PATH)
	var parsed: Variant = JSON.parse_string(text)
	_table = parsed if parsed is Dictionary else {}


func test_the_table_is_of_this_build_s_versions() -> void:
	assert_false(_table.is_empty(), "%s reads as a table" % GoldenRuns.TABLE_PATH)
	var recorded: Dictionary = _table.get("versions", {})
	var now := GoldenRuns.versions()
	var same_physics := int(recorded.get("physics", -1)) == int(now["physics"])
	var recorded_rules: Dictionary = recorded.get("rules", {})
	var same_rules := true
	for game: String in now["rules"]:
		same_rules = same_rules and int(recorded_rules.get(game, -1)) == int(now["rules"][game])
	assert_true(
		same_physics and same_rules,
		(
			(
				"the golden hashes were recorded with physics %s and rules %s; this build is physics"
				+ " %s, rules %s: run `make golden` to re-record them"
			)
			% [recorded.get("physics"), recorded_rules, now["physics"], now["rules"]]
		)
	)


func test_every_golden_run_gives_its_hash() -> void:
	var hashes: Dictionary = _table.get("hashes", {})
	var names := GoldenRuns.names()
	assert_eq(
		hashes.keys().size(),
		names.size(),
		"the table has a hash for every golden run (a board added or removed: `make golden`)"
	)
	for name in names:
		if not hashes.has(name):
			fail_test("%s: not in the table: `make golden` records it" % name)
			continue
		var now := GoldenRuns.hash_of(name)
		assert_eq(
			now,
			int(hashes[name]),
			(
				(
					"%s: state hash %d, the table's %d. The balls moved while PHYSICS_VERSION (%d)"
					+ " and the rules versions stayed: if that is meant, bump PHYSICS_VERSION"
					+ " (scripts/physics/ball_world.gd) or the game's rules version and re-record"
					+ " with `make golden`"
				)
				% [name, now, int(hashes[name]), BallWorld.PHYSICS_VERSION]
			)
		)
