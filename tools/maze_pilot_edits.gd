extends SceneTree
## Plays a maze board after small designer edits: every end of every inner wall moved one
## cell right, left, down and up in turn (an edit the validator refuses is skipped), one
## pilot game each, and prints a line per edit (won or not, balls in the goal, the
## validator's warnings), then how many were lost. For finding edits a person would still
## win that the pilot loses:
##   tools/godot.sh --headless --path . -s res://tools/maze_pilot_edits.gd -- --board=courtyards
## Options after `--`: `--board=ID` (a file in levels/maze/), `--seed=N` (1), `--hard`,
## `--slanted` (only the edits that slant a wall).

const SECONDS := 120.0


func _initialize() -> void:
	var args := {}
	for arg in OS.get_cmdline_user_args():
		var parts := arg.trim_prefix("--").split("=", true, 1)
		args[parts[0]] = parts[1] if parts.size() > 1 else "1"
	var loaded := BoardLoader.load_board("res://levels/maze/%s.board" % args.get("board", ""))
	if loaded.level == null:
		printerr("maze_pilot_edits: %s" % loaded.error)
		quit(1)
		return
	var lost := 0
	var played := 0
	for edited in _edits(loaded.level, args.has("slanted")):
		var result := MazeAutoplay.run(
			edited["level"], SECONDS, int(args.get("seed", "1")), args.has("hard")
		)
		played += 1
		if not result["won"]:
			lost += 1
		print(
			(
				"%s: won %s, %d in the goal, %d lost in holes %s"
				% [
					edited["what"],
					result["won"],
					result["balls_in_goal"],
					result["balls_lost_in_holes"],
					edited["warnings"],
				]
			)
		)
	print("%d of %d edits lost" % [lost, played])
	quit(0)


# Every accepted one-cell move of an inner wall end: {level, what, warnings}.
func _edits(level: BoardLevel, slanted_only: bool) -> Array[Dictionary]:
	var cell := level.size.x / float(level.grid_cols)
	var steps: Array[Vector2] = [
		Vector2(cell, 0.0), Vector2(-cell, 0.0), Vector2(0.0, cell), Vector2(0.0, -cell)
	]
	var area := Rect2(Vector2.ZERO, level.size)
	var found: Array[Dictionary] = []
	for i in level.walls.size():
		var end := level.walls[i]
		if not area.grow(-0.5).has_point(end):
			continue  # the frame's own walls stay
		var other := level.walls[i ^ 1]
		for step in steps:
			var moved := end + step
			var slants := moved.x != other.x and moved.y != other.y
			if moved == other or not area.grow(0.5).has_point(moved):
				continue
			if slanted_only and not slants:
				continue
			var edited := level.duplicate(true) as BoardLevel
			var walls := edited.walls.duplicate()
			walls[i] = moved
			edited.walls = walls
			if not BoardValidator.errors(edited).is_empty():
				continue
			var warnings := PackedStringArray()
			for issue in BoardValidator.validate(edited):
				warnings.append(issue.code)
			(
				found
				. append(
					{
						"level": edited,
						"what": "wall end %s -> %s" % [end, moved],
						"warnings": " ".join(warnings),
					}
				)
			)
	return found
