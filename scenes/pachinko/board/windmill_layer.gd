class_name WindmillLayer
extends Node2D
## The windmills of a pachinko board, turning: each frame every wheel is drawn at the angle
## its world reports (the world turns them; this only reads). Drawn above the pins and
## under the balls.

var _rules: PachinkoRules


## Draws the windmills of `rules` (its level's specs at its world's angles).
func bind(rules: PachinkoRules) -> void:
	_rules = rules
	set_process(not rules.level.windmills.is_empty())
	queue_redraw()


func _process(_delta: float) -> void:
	queue_redraw()


func _draw() -> void:
	if _rules == null or _rules.world == null:
		return
	var specs := _rules.level.windmills
	var world := _rules.world
	# World windmill i is the level's windmill i (BoardWorldFactory).
	for i in mini(specs.size(), world.shapes.windmill_count()):
		WindmillPainter.draw_wheel(self, specs[i], world.shapes.get_windmill_angle(i))
