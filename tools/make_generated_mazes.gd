extends SceneTree
## Regenerates the maze boards made with MazeGenerator (scripts/maze/generator/) and saves
## each as levels/maze/<id>.board; the same settings always write the same file:
##   tools/godot.sh --headless --path . -s res://tools/make_generated_mazes.gd
## Medal times are kept from the file already there (tools/maze_pilot_table.gd
## --write-medals sets them from the autoplay pilot's times). Afterwards
## tools/make_board_scenes.gd adds a level scene for any new board.

## One row per board: id, title, blurb, cols, rows, holes, difficulty, seed. Garden Path is
## no longer made here: it came from 6 x 6, 2 holes, difficulty 0, seed 11, and trial 8 moved
## three of its walls by hand (a wall at each turn, no part-way stops); regenerating it would
## undo that.
const BOARDS := [
	[
		"cloister",
		"Cloister",
		"Short corridors round a quiet goal room, loops to try; in hard mode, two holes to steer round.",
		8,
		7,
		2,
		0.0,
		7,
	],
	[
		"switchbacks",
		"Switchbacks",
		"Learn the small tilt: ten by ten cells of turns that double back, with stops part-way.",
		10,
		10,
		5,
		0.3,
		3,
	],
	[
		"crossroads",
		"Crossroads",
		"A wide maze where many ways cross: pick the one that keeps all four together.",
		12,
		9,
		6,
		0.35,
		21,
	],
	[
		"long_hall",
		"Long Hall",
		"Fourteen cells across and only six down: long rolls, sharp stops.",
		14,
		6,
		6,
		0.4,
		5,
	],
	[
		"tower",
		"Tower",
		"A tall, narrow maze: the balls climb and fall past holes on every floor.",
		7,
		10,
		7,
		0.5,
		9,
	],
	[
		"undercroft",
		"Undercroft",
		"Below the catacombs: fewer loops, and holes in the corridors as well as the dead ends.",
		12,
		9,
		10,
		0.6,
		13,
	],
	[
		"labyrinth",
		"Labyrinth",
		"Few ways round and ten holes: patience wins here.",
		13,
		9,
		10,
		0.7,
		17,
	],
	[
		"the_deep",
		"The Deep",
		"The largest maze, with the fewest loops and a dozen holes.",
		14,
		9,
		12,
		0.85,
		19,
	],
]


func _initialize() -> void:
	var failed := false
	for row: Array in BOARDS:
		var settings := MazeGenSettings.new()
		(
			settings
			. read(
				{
					"id": row[0],
					"title": row[1],
					"blurb": row[2],
					"cols": row[3],
					"rows": row[4],
					"holes": row[5],
					"difficulty": row[6],
					"seed": row[7],
				}
			)
		)
		var made := MazeGenerator.generate(settings)
		if made.has("error"):
			printerr("%s: %s" % [settings.id, made["error"]])
			failed = true
			continue
		var level: BoardLevel = made["level"]
		var path := "res://levels/maze/%s.board" % settings.id
		MedalRule.keep_file_medals(level, path)
		var error := ResourceSaver.save(level, path)
		if error != OK:
			printerr("%s: could not save (%s)" % [path, error_string(error)])
			failed = true
			continue
		print("%s: %d × %d, %d holes" % [path, settings.cols, settings.rows, made["holes_placed"]])
	quit(1 if failed else 0)
