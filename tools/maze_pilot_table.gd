extends SceneTree
## Plays every maze board in levels/maze/ with the autoplay pilot and prints a Markdown
## table: easy mode with seed 1, hard mode with seeds 1..5 (wins, balls lost, how near a
## ball came to a hole, times).
##   tools/godot.sh --headless --path . -s res://tools/maze_pilot_table.gd
## Options after `--`: `--board=ID` (one board), `--hard-seeds=N` (seeds 1..N in hard mode),
## `--write-medals` (store medal times from the pilot's times in each board file by
## MedalRule, and what the pilot measured in MedalRule.PILOT_RECORD), `--from-record` (with
## --write-medals: plays nothing, makes the medal times again from the record by the rule as
## it is now, for a change to MedalRule; a board changed since it was measured is refused).
## Exits 1 when a board fails easy seed 1 or hard wins fall under 80 %.

const MAZE_DIR := "res://levels/maze/"
const SECONDS := 120.0
const HARD_TARGET := 0.8


func _initialize() -> void:
	var options := _options()
	var hard_seeds: int = options.get("hard_seeds", 5)
	var only: String = options.get("board", "")
	if options.has("from_record") and options.has("write_medals"):
		quit(_medals_from_record())
		return
	print("| board | easy s1 | hard wins | hard lost balls | closest to a hole | hard times |")
	print("|---|---|---|---|---|---|")
	var hard_won := 0
	var hard_runs := 0
	var easy_failed := 0
	for file in _board_files():
		var loaded := BoardLoader.load_board(MAZE_DIR + file)
		if loaded.level == null:
			printerr(loaded.error)
			easy_failed += 1
			continue
		var level := loaded.level
		if not only.is_empty() and level.board_id != only and file.get_basename() != only:
			continue
		var easy := MazeAutoplay.run(level, SECONDS, 1, false)
		var easy_time: float = MedalRule.rounded(easy["time_to_win"]) if easy["won"] else -1.0
		if not easy["won"]:
			easy_failed += 1
		var wins := 0
		var lost := 0
		var times := PackedFloat64Array()
		var closest := INF
		for s in range(1, hard_seeds + 1):
			var hard := MazeAutoplay.run(level, SECONDS, s, true)
			lost += int(hard["balls_lost_in_holes"])
			if float(hard["closest_hole_gap"]) >= 0.0:
				closest = minf(closest, float(hard["closest_hole_gap"]))
			if hard["won"]:
				wins += 1
				times.append(MedalRule.rounded(hard["time_to_win"]))
		hard_won += wins
		hard_runs += hard_seeds
		print(
			(
				"| %s | %s | %d/%d | %d | %s | %s |"
				% [
					file.get_basename(),
					("%.1f s" % easy_time) if easy["won"] else "LOST",
					wins,
					hard_seeds,
					lost,
					("%.1f px" % closest) if is_finite(closest) else "-",
					", ".join(Array(times).map(func(t: float) -> String: return "%.1f" % t)),
				]
			)
		)
		if options.has("write_medals"):
			_write_medals(MAZE_DIR + file, level, easy_time, times)
	var rate := float(hard_won) / maxf(1.0, float(hard_runs))
	print("hard mode: %d of %d won (%.0f %%)" % [hard_won, hard_runs, rate * 100.0])
	quit(0 if easy_failed == 0 and rate >= HARD_TARGET else 1)


func _write_medals(path: String, level: BoardLevel, easy: float, hard: PackedFloat64Array) -> void:
	var made := MedalRule.medal_times(easy, hard, not level.holes.is_empty())
	level.medal_times_easy = made[0]
	level.medal_times_hard = made[1]
	if hard.is_empty() and not level.holes.is_empty():
		print("%s: no hard win, hard medals from the easy time" % path)
	var error := ResourceSaver.save(level, path)
	if error != OK:
		printerr("could not save %s: %s" % [path, error_string(error)])
		return
	var record := {}
	if FileAccess.file_exists(MedalRule.PILOT_RECORD):
		var old: Variant = JSON.parse_string(FileAccess.get_file_as_string(MedalRule.PILOT_RECORD))
		if old is Dictionary:
			record = old
	record[level.board_id] = {
		"board": MedalRule.fingerprint(FileAccess.get_file_as_string(path)),
		"easy": easy,
		"hard": Array(hard),
	}
	var keys := record.keys()
	keys.sort()
	var lines := PackedStringArray()
	for key: String in keys:
		lines.append("  %s: %s" % [JSON.stringify(key), JSON.stringify(record[key], "", true)])
	var file := FileAccess.open(MedalRule.PILOT_RECORD, FileAccess.WRITE)
	if file == null:
		printerr("could not write %s" % MedalRule.PILOT_RECORD)
		return
	file.store_string("{\n%s\n}\n" % ",\n".join(lines))


# Medal times again from the pilot's record, playing nothing; 1 when a board changed since.
func _medals_from_record() -> int:
	var parsed: Variant = JSON.parse_string(FileAccess.get_file_as_string(MedalRule.PILOT_RECORD))
	var record: Dictionary = parsed if parsed is Dictionary else {}
	var refused := 0
	for file in _board_files():
		var path := MAZE_DIR + file
		var level := BoardLoader.load_board(path).level
		var entry: Dictionary = record.get(level.board_id, {}) if level != null else {}
		if (
			entry.is_empty()
			or entry["board"] != MedalRule.fingerprint(FileAccess.get_file_as_string(path))
		):
			printerr("%s: changed since the pilot measured it; play it again" % path)
			refused += 1
			continue
		_write_medals(path, level, float(entry["easy"]), PackedFloat64Array(entry["hard"]))
		print(
			(
				"%s: easy %s, hard %s"
				% [file.get_basename(), level.medal_times_easy, level.medal_times_hard]
			)
		)
	return 0 if refused == 0 else 1


func _board_files() -> PackedStringArray:
	var files := PackedStringArray()
	for file in DirAccess.get_files_at(MAZE_DIR):
		if file.get_extension() == "board":
			files.append(file)
	files.sort()
	return files


func _options() -> Dictionary:
	var options := {}
	for arg in OS.get_cmdline_user_args():
		if arg.begins_with("--board="):
			options["board"] = arg.trim_prefix("--board=")
		elif arg.begins_with("--hard-seeds="):
			options["hard_seeds"] = maxi(1, arg.trim_prefix("--hard-seeds=").to_int())
		elif arg == "--write-medals":
			options["write_medals"] = true
		elif arg == "--from-record":
			options["from_record"] = true
	return options
