extends SceneTree
## make golden: records the golden replays again and writes every golden run's state hash,
## with the physics and rules versions, to tests/golden/golden_hashes.json. Run it after a
## change that is meant to move the balls, with PHYSICS_VERSION (or the game's rules
## version) bumped; test_golden_hashes.gd then holds the new figures.

const GoldenRuns := preload("res://tests/golden/golden_runs.gd")


func _initialize() -> void:
	for game: String in GoldenRuns.REPLAYS:
		var problem := GoldenRuns.record_replay(game)
		if not problem.is_empty():
			printerr("golden: ", problem)
			quit(1)
			return
	var hashes := {}
	for name in GoldenRuns.names():
		hashes[name] = GoldenRuns.hash_of(name)
		print("golden: %-40s %d" % [name, hashes[name]])
	var table := {"versions": GoldenRuns.versions(), "hashes": hashes}
	var file := FileAccess.open(GoldenRuns.TABLE_PATH, FileAccess.WRITE)
	if file == null:
		printerr("golden: cannot write %s" % GoldenRuns.TABLE_PATH)
		quit(1)
		return
	file.store_string(JSON.stringify(table, "\t", false) + "\n")
	file.close()
	print("golden: %d hashes written to %s" % [hashes.size(), GoldenRuns.TABLE_PATH])
	quit(0)
