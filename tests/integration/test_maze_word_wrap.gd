extends GutTest
## Player text wraps only between words: trial 7 read "Tilt the board to star / t!" in the
## maze side panel, which used AUTOWRAP_WORD_SMART (it breaks a word that does not fit the
## width at the moment of layout). Every wrapping label now uses AUTOWRAP_WORD.

const GAME := preload("res://scenes/maze/maze_game.tscn")
const StretchedWindow := preload("res://tests/integration/stretched_window.gd")
const SIZES: Array[Vector2i] = [Vector2i(1280, 720), Vector2i(720, 1280)]
const SOURCE_DIRS: Array[String] = ["res://scenes", "res://scripts"]


func test_the_maze_side_panel_wraps_at_word_boundaries() -> void:
	for size in SIZES:
		var game := await StretchedWindow.open(self, GAME, size, 3) as MazeGame
		var side: Control = game.get_node("Side")
		var checked := 0
		for node in side.find_children("*", "Label", true, false):
			var label := node as Label
			checked += 1
			var mode := label.autowrap_mode
			assert_true(
				mode == TextServer.AUTOWRAP_OFF or mode == TextServer.AUTOWRAP_WORD,
				"%s: %s wraps with mode %d" % [size, label.name, mode]
			)
		assert_gte(checked, 5, "the panel's labels were looked at")
		game.free()


func test_no_scene_or_script_breaks_words() -> void:
	var found: Array[String] = []
	for dir in SOURCE_DIRS:
		_scan(dir, found)
	assert_eq(found, [] as Array[String], "files that wrap inside words")


func _scan(dir: String, found: Array[String]) -> void:
	for sub in DirAccess.get_directories_at(dir):
		_scan(dir.path_join(sub), found)
	for file in DirAccess.get_files_at(dir):
		if not (file.ends_with(".gd") or file.ends_with(".tscn")):
			continue
		var path := dir.path_join(file)
		var text := FileAccess.get_file_as_string(path)
		# Built from parts so that this file does not match itself.
		for bad: String in [
			"AUTOWRAP_" + "WORD_SMART",
			"AUTOWRAP_" + "ARBITRARY",
			"autowrap_mode = 3",
			"autowrap_mode = 1\n"
		]:
			if bad in text:
				found.append("%s (%s)" % [path, bad.strip_edges()])
