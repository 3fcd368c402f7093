extends GutTest
## BallWorld on the classic maze against the tilt maze tutorial's own JavaScript: the same
## scripted tilts, frame by frame (tests/fixtures/seed_reference, recorded by
## tools/seed_reference/record.js). The classic board's tuning takes the seed's options:
## a per-axis speed cap, friction against the downhill direction, caps that glance.
##
## Tolerance: every frame's ball position within TOLERANCE px (half a ball radius) of the
## seed's; measured worst cases are 0.35 to 2.1 px. The two cannot agree exactly: BallWorld
## takes two 8 ms steps per 16 ms seed frame and sweeps its contacts; it caps both axes the
## same way, where the seed caps x before its friction and y after (its x tops out 0.02 px a
## frame slower); a ball resting on a wall rests, where the seed bounces it 0.1 px a frame;
## and the seed tests caps where a ball would be at the frame's end, BallWorld where it is.

const CLASSIC := "res://levels/maze/classic.board"
const FIXTURES := "res://tests/fixtures/seed_reference/"
const SCENARIOS: Array[String] = [
	"straight_x",
	"straight_y",
	"diagonal_12_4",
	"diagonal_45",
	"round_cap",
	"head_on_cap",
	"off_wall",
	"corner_12_12"
]
## The seed's frame: its main() counts time in 16 ms units.
const SEED_FRAME := 0.016
## Largest distance (px) between the two balls at any frame: half the ball's radius.
const TOLERANCE := 2.5
## The corner case's own tolerance (px). A ball rolled dead at a cap slides off it as the
## seed's does, but 1 to 2 frames later (the seed puts it back on the cap where its whole
## 16 ms move would end, BallWorld after each 8 ms step), so along the wall after it the two
## run up to 2.2 px apart, and 3.7 px for the frame where both leave the wall's far cap.
const CORNER_TOLERANCE := 4.0
## The corner case's cap: the top-left ball meets it dead on along the diagonal.
const CORNER_CAP := Vector2(35.0, 35.0)


## Runs scenario `name` on the classic board (with `tuning` instead of the board's when
## given): {"max": worst distance in px, "at": its frame, "end": distance at the last frame,
## "left_cap": the first frame the ball is 12 px past CORNER_CAP's centre line (-1 if never),
## "seed_left_cap": the same frame for the seed's ball}.
func _run_beside_seed(name: String, tuning: PhysicsTuning = null) -> Dictionary:
	var text := FileAccess.get_file_as_string(FIXTURES + name + ".json")
	var data: Variant = JSON.parse_string(text)
	assert_true(data is Dictionary, "%s.json parses" % name)
	if not data is Dictionary:
		return {"max": INF, "at": -1, "end": INF}
	var fixture: Dictionary = data
	var level: BoardLevel = BoardLoader.load_board(CLASSIC).level
	if tuning != null:
		level.tuning = tuning
	var world := BoardWorldFactory.build(level)
	var start: Array = fixture["start"]
	var id := world.spawn_ball(Vector2(start[0], start[1]), Vector2.ZERO, level.ball_radius)
	var steps := maxi(roundi(SEED_FRAME * world.tuning.fixed_hz), 1)
	var tilts: Array = fixture["tilts"]
	var frames: Array = fixture["frames"]
	var worst := 0.0
	var worst_at := -1
	var dist := 0.0
	var left_cap := -1
	var seed_left_cap := -1
	for f in frames.size():
		for change: Dictionary in tilts:
			if int(change["frame"]) == f:
				var deg: Array = change["deg"]
				MazeTilt.apply(world, Vector2(deg[0], deg[1]))
		for _s in steps:
			world.step(SEED_FRAME / steps)
		var row: Array = frames[f]
		var seed_at := Vector2(row[0], row[1])
		var at := world.get_ball_position(id)
		dist = at.distance_to(seed_at)
		if dist > worst:
			worst = dist
			worst_at = f
		if left_cap < 0 and _past_corner_cap(at):
			left_cap = f
		if seed_left_cap < 0 and _past_corner_cap(seed_at):
			seed_left_cap = f
	return {
		"max": worst,
		"at": worst_at,
		"end": dist,
		"left_cap": left_cap,
		"seed_left_cap": seed_left_cap
	}


## True once a ball has slid off CORNER_CAP on either side: 12 px past its centre in x or y.
func _past_corner_cap(at: Vector2) -> bool:
	return at.x > CORNER_CAP.x + 12.0 or at.y > CORNER_CAP.y + 12.0


func test_ball_world_follows_the_seed_on_every_scripted_tilt() -> void:
	for name in SCENARIOS:
		var result := _run_beside_seed(name)
		var line := "%s: worst %.3f px at frame %d, end %.3f px"
		gut.p(line % [name, result["max"], result["at"], result["end"]])
		var limit := CORNER_TOLERANCE if name == "corner_12_12" else TOLERANCE
		assert_lte(float(result["max"]), limit, "%s: %s" % [name, result])


func test_a_ball_rolled_dead_at_a_corner_cap_slides_off_it_as_the_seeds_does() -> void:
	# The joystick in its corner: the seed's x tops out at 1.48 px a frame and y at 1.5, so
	# the ball meets the cap at (35, 35) a hair off its diagonal and slides off downwards.
	var result := _run_beside_seed("corner_12_12")
	gut.p(
		(
			"corner: seed leaves the cap at frame %d, BallWorld at %d"
			% [result["seed_left_cap"], result["left_cap"]]
		)
	)
	assert_between(
		int(result["seed_left_cap"]), 10, 30, "the recorded seed slides off: %s" % [result]
	)
	assert_between(
		int(result["left_cap"]),
		int(result["seed_left_cap"]),
		int(result["seed_left_cap"]) + 3,
		"within 3 frames of the seed: %s" % [result]
	)
	# Both axes capped alike, the ball sits on the cap for all 600 frames.
	var even: PhysicsTuning = BoardLoader.load_board(CLASSIC).level.tuning.duplicate()
	even.x_cap_friction_time = 0.0
	var stuck := _run_beside_seed("corner_12_12", even)
	assert_eq(int(stuck["left_cap"]), -1, "caps alike, it never leaves: %s" % [stuck])


func test_the_seed_options_are_what_makes_it_match() -> void:
	# The same board with the seed options off: a total speed cap, friction against the
	# velocity, caps rolled round. Capped in total, a (12°, 4°) tilt rolls along the tilt
	# instead of at about 45°, and a 45° run 29% slower.
	var tuning: PhysicsTuning = BoardLoader.load_board(CLASSIC).level.tuning.duplicate()
	tuning.speed_cap = PhysicsTuning.SpeedCap.TOTAL
	tuning.friction_against = PhysicsTuning.FrictionAgainst.VELOCITY
	tuning.wall_cap_contact = PhysicsTuning.CapContact.ROLL_ROUND
	for name: String in ["diagonal_12_4", "diagonal_45"]:
		var result := _run_beside_seed(name, tuning)
		gut.p("without the seed options, %s: worst %.3f px" % [name, result["max"]])
		assert_gt(float(result["max"]), TOLERANCE, "%s departs from the seed: %s" % [name, result])


func test_head_on_into_a_cap_stops_dead_and_stays() -> void:
	var level: BoardLevel = BoardLoader.load_board(CLASSIC).level
	var result := _drop_onto_cap(level)
	assert_almost_eq(float(result["end_y"]), 130.0, 0.01, "resting on the cap")
	assert_gt(float(result["min_vy"]), -1.0, "no bounce back: %s" % [result])
	# The contrast: rolled round like any round surface, the cap bounces it back a third.
	level.tuning.wall_cap_contact = PhysicsTuning.CapContact.ROLL_ROUND
	var rolled := _drop_onto_cap(level)
	assert_lt(float(rolled["min_vy"]), -20.0, "ROLL_ROUND bounces: %s" % [rolled])


## Drops a ball straight down onto the top cap of the wall from (210, 140) to (210, 175):
## {"end_y": where it ends, "min_vy": its fastest upward speed (px/s, negative)}.
func _drop_onto_cap(level: BoardLevel) -> Dictionary:
	var world := BoardWorldFactory.build(level)
	var id := world.spawn_ball(Vector2(210.0, 110.0), Vector2.ZERO, level.ball_radius)
	MazeTilt.apply(world, Vector2(0.0, 12.0))
	var min_vy := 0.0
	for _s in 60:
		world.step(1.0 / world.tuning.fixed_hz)
		min_vy = minf(min_vy, world.get_ball_velocity(id).y)
	return {"end_y": world.get_ball_position(id).y, "min_vy": min_vy}
