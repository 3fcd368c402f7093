extends GutTest
## Gates (BallWorld.add_gate / add_petal): petals hinged at one end that swing between a
## shut and an open pose, on command or on a schedule. A ball never passes through a
## swinging petal at any petal or ball speed up to the top speed; a closing petal throws a
## ball; schedules run by themselves; 1, 2 and 4 threads give the same world.

const DT := 1.0 / 120.0
const BALL_R := 5.0
const PETAL_R := 2.0
const LENGTH := 30.0
## The petal points straight up when open and along +x when shut: closing swings it
## clockwise on screen through the quarter above the x axis.
const OPEN_ANGLE := -PI / 2.0
const SHUT_ANGLE := 0.0


func _empty_world() -> BallWorld:
	var w := BallWorld.new(TuningPresets.pachinko())
	w.gravity = Vector2.ZERO
	return w


## A world with one gate of one petal hinged at the origin, `swing` s to swing fully.
func _one_petal(swing: float) -> BallWorld:
	var w := _empty_world()
	var gate: int = w.shapes.add_gate(swing)
	w.shapes.add_petal(gate, Vector2.ZERO, LENGTH, PETAL_R, SHUT_ANGLE, OPEN_ANGLE)
	return w


## An open petal starts closing with its tip at `tip_speed` px/s while a ball, `radius` px
## from the hinge in the middle of the swept quarter, is fired at `ball_speed` px/s
## straight at the petal's open pose (against its swing). Returns the worst seen at every
## substep: "crossed" (from one side of the petal to the other within its length) and
## "depth" (deepest inside the petal's grown capsule, px).
func _fire_at_closing_petal(tip_speed: float, ball_speed: float, radius: float) -> Dictionary:
	var swing: float = absf(SHUT_ANGLE - OPEN_ANGLE) * (LENGTH + PETAL_R) / tip_speed
	var w := _one_petal(swing)
	w.shapes.set_gate_open(0, true, true)
	w.shapes.set_gate_open(0, false)
	w.build_grid()
	var at := Vector2.from_angle(-PI / 4.0) * radius
	w.spawn_ball(at, Vector2(-1.0, -0.3).normalized() * ball_speed, BALL_R)
	w.set_path_recording(true)
	var worst := {"crossed": false, "depth": 0.0}
	var prev := w.get_ball_position(0)
	var prev_turn: float = w.shapes.get_petal_angle(0)
	for _step: int in 40:
		var turn0: float = w.shapes.get_petal_angle(0)
		w.step(DT)
		var turn1: float = w.shapes.get_petal_angle(0)
		var points: PackedVector2Array = w.take_step_paths()["points"]
		points.append(w.get_ball_position(0))
		var n: int = points.size()
		for j: int in n:
			var turn: float = lerpf(turn0, turn1, float(j + 1) / float(n))
			_look(points[j], turn, prev, prev_turn, worst)
			prev = points[j]
			prev_turn = turn
	return worst


# Notes how deep `p` is in the petal at angle `turn`, and whether the move from `prev`
# (petal at `prev_turn`) crossed it within its length.
func _look(p: Vector2, turn: float, prev: Vector2, prev_turn: float, worst: Dictionary) -> void:
	var dir := Vector2.from_angle(turn)
	var along: float = p.dot(dir)
	var q: Vector2 = dir * clampf(along, 0.0, LENGTH)
	var depth: float = (PETAL_R + BALL_R) - p.distance_to(q)
	worst["depth"] = maxf(worst["depth"], depth)
	var prev_dir := Vector2.from_angle(prev_turn)
	var prev_along: float = prev.dot(prev_dir)
	var inside_span: bool = along > 0.0 and along < LENGTH and prev_along > 0.0
	inside_span = inside_span and prev_along < LENGTH
	var across: float = dir.cross(p)
	if inside_span and across != 0.0 and signf(across) != signf(prev_dir.cross(prev)):
		worst["crossed"] = true


func test_a_ball_fired_at_a_closing_petal_never_passes_through_or_ends_inside_it() -> void:
	var top: float = TuningPresets.pachinko().max_speed
	var failures := PackedStringArray()
	for tip_step: int in range(1, 5):
		var tip_speed: float = top * tip_step / 4.0
		for ball_step: int in 9:
			var ball_speed: float = top * ball_step / 8.0
			for radius: float in [12.0, 20.0, 27.0]:
				var seen := _fire_at_closing_petal(tip_speed, ball_speed, radius)
				var depth: float = seen["depth"]
				if seen["crossed"] or depth > 0.05:
					var what := "tip %d px/s, ball %d px/s, %d px out: crossed %s, depth %.2f px"
					failures.append(what % [tip_speed, ball_speed, radius, seen["crossed"], depth])
	assert_eq(failures, PackedStringArray(), "no ball passes through or ends in a petal")


func test_a_gate_swings_over_its_swing_time_and_stops_at_each_pose() -> void:
	var w := _one_petal(0.25)
	assert_almost_eq(w.shapes.get_petal_angle(0), SHUT_ANGLE, 1e-12, "a new gate is shut")
	w.shapes.set_gate_open(0, true)
	for _i: int in 15:
		w.step(DT)
	assert_almost_eq(w.shapes.get_gate_openness(0), 0.5, 1e-9, "half open after half its swing")
	assert_almost_eq(w.shapes.get_petal_angle(0), lerpf(SHUT_ANGLE, OPEN_ANGLE, 0.5), 1e-9)
	for _i: int in 30:
		w.step(DT)
	assert_eq(w.shapes.get_gate_openness(0), 1.0, "open, and no further")
	assert_almost_eq(w.shapes.get_petal_angle(0), OPEN_ANGLE, 1e-12)
	w.shapes.set_gate_open(0, false, true)
	assert_eq(w.shapes.get_gate_openness(0), 0.0, "at_once shuts it now")
	assert_almost_eq(w.shapes.get_petal_angle(0), SHUT_ANGLE, 1e-12)


func test_a_petal_tip_never_outruns_the_top_speed() -> void:
	var w := _one_petal(0.001)
	w.shapes.set_gate_open(0, true)
	w.step(DT)
	var turned: float = absf(w.shapes.get_petal_angle(0) - SHUT_ANGLE)
	var tip_travel: float = turned * (LENGTH + PETAL_R)
	assert_almost_eq(tip_travel, w.tuning.max_speed * DT, 1e-6, "held to the top speed")


func test_a_scheduled_gate_opens_and_shuts_by_itself() -> void:
	var w := _one_petal(0.1)
	w.shapes.set_gate_schedule(0, 0.5, 0.5)
	var seen_open := 0
	var seen_shut := 0
	for i: int in 240:
		w.step(DT)
		if w.shapes.get_gate_openness(0) == 1.0:
			seen_open += 1
		elif w.shapes.get_gate_openness(0) == 0.0 and i > 0:
			seen_shut += 1
	# Two seconds from shut: 0.5 s shut, then twice 0.5 s heading open (0.1 s of swing, so
	# 48 steps open) and once 0.5 s heading shut (48 steps shut) in between.
	assert_between(seen_open, 94, 98, "open 0.4 s of each opening")
	assert_between(seen_shut, 105, 109, "shut at first, and 0.4 s of the closing")


func test_a_closing_petal_throws_a_ball_and_reports_the_gate() -> void:
	var w := _one_petal(0.1)
	w.shapes.set_gate_open(0, true, true)
	w.build_grid()
	var id: int = w.spawn_ball(Vector2.from_angle(-PI / 4.0) * 20.0, Vector2.ZERO, BALL_R)
	var hits: Array = []
	w.gate_hit.connect(func(b: int, g: int, s: float) -> void: hits.append([b, g, s]))
	w.shapes.set_gate_open(0, false)
	for _i: int in 12:
		w.step(DT)
	var v: Vector2 = w.get_ball_velocity(id)
	assert_gt(v.length(), 100.0, "the swinging petal threw the resting ball")
	assert_gt(v.dot(Vector2.from_angle(PI / 4.0)), 0.0, "forward of the petal's swing")
	assert_false(hits.is_empty(), "gate_hit names the gate")
	if not hits.is_empty():
		assert_eq(hits[0][1], 0)


func test_bad_gates_are_refused_with_an_error() -> void:
	var w := _empty_world()
	assert_eq(w.shapes.add_gate(0.0), -1)
	assert_eq(w.shapes.add_gate(NAN), -1)
	assert_eq(w.shapes.add_petal(0, Vector2.ZERO, LENGTH, PETAL_R, 0.0, 1.0), -1, "no gate 0 yet")
	var gate: int = w.shapes.add_gate(0.2)
	assert_eq(w.shapes.add_petal(gate, Vector2.ZERO, -1.0, PETAL_R, 0.0, 1.0), -1, "length > 0")
	assert_eq(w.shapes.add_petal(gate, Vector2.ZERO, LENGTH, PETAL_R, INF, 1.0), -1)
	w.shapes.set_gate_schedule(gate, -1.0, 0.5)
	assert_eq(w.shapes.gate_count(), 1)
	assert_eq(w.shapes.windmill_count(), 0, "a petal is not a windmill")
	assert_push_error_count(6)


func test_windmills_and_petals_keep_their_own_numbers() -> void:
	var w := _empty_world()
	var gate: int = w.shapes.add_gate(0.2)
	w.shapes.add_petal(gate, Vector2(100.0, 0.0), LENGTH, PETAL_R, 0.0, -1.0)
	var mill: int = w.shapes.add_windmill(Vector2.ZERO, 4, 20.0, 2.0, 3.0)
	assert_eq(mill, 0, "the first windmill is windmill 0, petals aside")
	assert_eq(w.shapes.windmill_count(), 1)
	w.step(DT)
	assert_almost_eq(w.shapes.get_windmill_angle(0), 3.0 * DT, 1e-9)
	assert_eq(w.shapes.get_petal_angle(0), 0.0, "the shut petal did not turn with the wheel")


func _gate_run(thread_count: int) -> int:
	var w := BallWorld.new(TuningPresets.pachinko())
	w.threads = thread_count
	for g: int in 6:
		var gate: int = w.shapes.add_gate(0.15 + 0.05 * g)
		var root := Vector2(60.0 + 50.0 * g, 200.0)
		w.shapes.add_petal(gate, root, 20.0, 2.5, -PI / 2.0, -PI / 2.0 - 0.9, 20.0)
		w.shapes.add_petal(
			gate, root + Vector2(26.0, 0.0), 20.0, 2.5, -PI / 2.0, -PI / 2.0 + 0.9, 20.0
		)
		w.shapes.set_gate_schedule(gate, 0.3 + 0.1 * g, 0.4)
	w.shapes.add_wall(Vector2(0.0, 260.0), Vector2(400.0, 260.0), 3.0)
	for k: int in 300:
		w.spawn_ball(Vector2(40.0 + (k * 37) % 320, 20.0 + (k % 12) * 12.0), Vector2.ZERO, 5.0)
	for _i: int in 240:
		w.step(DT)
	return w.state_hash()


func test_gate_world_is_bit_identical_for_1_2_and_4_threads() -> void:
	var one := _gate_run(1)
	assert_eq(_gate_run(2), one, "2 threads")
	assert_eq(_gate_run(4), one, "4 threads")
