extends GutTest
## The goal's dish is drawn clear of every wall on every shipped maze board: a play trial saw
## the dish of First Roll and Two Together half under the corridor's walls (28 px of dish in a
## 25 px corridor), and Classic's under its room's walls. The dish reaches the goal's radius
## plus the lip the floor draws round it; a wall reaches half its width from its centre line
## (round caps included).

const MAZE_DIR := "res://levels/maze/"
const Board3D := preload("res://scenes/maze/maze_board_3d.gd")


func _boards() -> Array[String]:
	var out: Array[String] = []
	for file in DirAccess.get_files_at(MAZE_DIR):
		if file.ends_with(".board"):
			out.append(MAZE_DIR + file)
	out.sort()
	return out


func test_every_shipped_goal_dish_is_clear_of_every_wall() -> void:
	var boards := _boards()
	assert_gt(boards.size(), 10, "the shipped maze boards are found")
	for path in boards:
		var level := BoardLoader.load_board(path).level
		var dish := level.goal_radius + Board3D.GOAL_LIP_PX
		for w in range(level.walls.size() >> 1):
			var a := level.walls[w * 2]
			var b := level.walls[w * 2 + 1]
			var near := Geometry2D.get_closest_point_to_segment(level.goal_center, a, b)
			var face := near.distance_to(level.goal_center) - level.wall_width * 0.5
			var problem := "%s: the goal's dish (%.1f px with its lip) reaches under the wall"
			problem += " %s-%s (its face %.1f px from the goal's middle)"
			assert_true(face >= dish, problem % [path.get_file(), dish, a, b, face])
