class_name BoardWorldFactory
extends RefCounted
## Builds the physics world for a board: the one place that turns level data into shapes.
##
## Pachinko: ring, gutter, pins (with pocket ids and special flags), the bonus pockets' pins
## and then their lids and wings (the first walls, see BonusGeometry), the launch rail's
## guide arc, its stopper and the deflector past its end as capsules (in that order), the
## reels' frame on a board with a start pocket, and the rail's return zone as zone 0, then
## the windmills (world windmill i = level windmill i; a null entry, refused by the
## validator, is skipped).
## Maze: the level's walls (same indices as in the level), then four invisible edge walls
## that keep balls on the board, the goal (goal 0) and, in hard mode only, the black holes.


## A ready world (grid built) for `level`; null with an error for a missing level.
static func build(level: BoardLevel, hard_mode: bool = false) -> BallWorld:
	if level == null:
		push_error("BoardWorldFactory.build: no level given")
		return null
	var world := BallWorld.new(tuning_for(level))
	if level.is_pachinko():
		_build_pachinko(world, level)
	else:
		_build_maze(world, level, hard_mode)
	world.build_grid()
	return world


## The level's tuning, or its game's preset (TuningPresets) when it has none.
static func tuning_for(level: BoardLevel) -> PhysicsTuning:
	if level.tuning != null:
		return level.tuning
	return TuningPresets.for_kind(level.is_maze())


static func _build_pachinko(world: BallWorld, level: BoardLevel) -> void:
	# The ring shares the pins' material: the chapter resolves a ring hit as a pin hit.
	var least_speed_x := maxf(world.tuning.min_horizontal_speed, 0.0)
	world.shapes.set_ring(level.ring_center, level.ring_radius, least_speed_x)
	var slide_time := maxf(world.tuning.drain_slide_time, 0.0)
	var bounces := maxi(level.gutter_bounces, 1)
	# The gutter: the drain arc of the ring.
	world.shapes.set_drain_arc(level.gutter_start_deg, level.gutter_end_deg, bounces, slide_time)
	var count := mini(level.pins.size(), mini(level.pin_pocket.size(), level.pin_special.size()))
	# The pins' material: the board's minimum horizontal speed after a touch.
	var min_speed_x := maxf(world.tuning.min_horizontal_speed, 0.0)
	for i in count:
		var special := level.pin_special[i] != 0
		world.shapes.add_pin(
			level.pins[i], level.pin_radius, level.pin_pocket[i], special, min_speed_x
		)
	# The bonus pockets: their cups after the level's pins, their lids as the first walls
	# and their tulips' wings as the gates, in order (BonusGeometry's contract with
	# BonusMachine).
	BonusGeometry.add_pins(world, level, min_speed_x)
	BonusGeometry.add_walls(world, level)
	BonusGeometry.add_gates(world, level, min_speed_x)
	var guide := LaunchRail.guide_points(level)
	for i in guide.size() - 1:
		world.shapes.add_wall(guide[i], guide[i + 1], LaunchRail.GUIDE_WALL_RADIUS)
	var stop := LaunchRail.stopper(level)
	world.shapes.add_wall(stop[0], stop[1], LaunchRail.GUIDE_WALL_RADIUS)
	var deflector := LaunchRail.deflector(level)
	world.shapes.add_wall(deflector[0], deflector[1], LaunchRail.GUIDE_WALL_RADIUS)
	# The reels' frame (boards with a start pocket): a solid piece balls bounce off.
	var frame := BonusGeometry.reel_frame(level)
	for k in range(0, frame.size(), 2):
		world.shapes.add_wall(frame[k], frame[k + 1], BonusGeometry.REEL_FRAME_RADIUS)
	# Zone 0: a ball that rolls back down the rail lands here and returns to the cup.
	world.shapes.add_zone(
		LaunchRail.return_zone_center(level), LaunchRail.return_zone_radius(level)
	)
	# The windmills: world windmill i is the level's windmill i; their blades share the
	# pins' material, so no ball balances in the V of two blades.
	for spec in level.windmills:
		if spec != null:
			add_windmill(world, spec, min_speed_x)


## Adds `spec` to `world` as a windmill (degrees in the board, radians in the world), its
## blades keeping a ball's horizontal speed at `min_speed_x` or more.
static func add_windmill(world: BallWorld, spec: WindmillSpec, min_speed_x: float) -> int:
	var speed := 0.0 if spec.free_spin else deg_to_rad(spec.speed)
	var friction := deg_to_rad(spec.friction) if spec.free_spin else 0.0
	return world.shapes.add_windmill(
		spec.position,
		spec.blades,
		spec.length,
		WindmillSpec.BLADE_RADIUS,
		speed,
		spec.free_spin,
		friction,
		min_speed_x
	)


static func _build_maze(world: BallWorld, level: BoardLevel, hard_mode: bool) -> void:
	@warning_ignore("integer_division")  # walls are stored as pairs of end points
	var wall_count := level.walls.size() / 2
	for w in wall_count:
		world.shapes.add_wall(level.walls[w * 2], level.walls[w * 2 + 1], level.wall_width * 0.5)
	# The board's edges hold the balls even where the design has no border wall.
	var corners: Array[Vector2] = [
		Vector2.ZERO, Vector2(level.size.x, 0.0), level.size, Vector2(0.0, level.size.y)
	]
	for i in 4:
		world.shapes.add_wall(corners[i], corners[(i + 1) % 4], 0.0)
	world.shapes.add_goal(level.goal_center, level.goal_radius)
	if hard_mode:
		for hole in level.holes:
			world.shapes.add_hole(hole, level.hole_radius)
