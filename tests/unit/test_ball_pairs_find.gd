extends GutTest
## BallPairs' broad phase against brute force: the pairs it lists over all stripes are
## exactly the touching pairs of the balls, each once, for mixed radii, crowded and lone
## balls, balls on stripe and row edges, and one lane or several.


func _world(threads: int, seed_value: int) -> BallWorld:
	var w := BallWorld.new(TuningPresets.pachinko())
	w.threads = threads
	w.shapes.set_ring(Vector2.ZERO, 300.0)
	var rng := RandomNumberGenerator.new()
	rng.seed = seed_value
	# A crowded heap, a sparse spray and a column of balls stacked through many rows.
	for _i: int in 500:
		var p := Vector2(rng.randf_range(-60, 60), rng.randf_range(100, 200))
		w.spawn_ball(p, Vector2.ZERO, rng.randf_range(3.0, 5.0))
	for _i: int in 300:
		var p := Vector2(rng.randf_range(-250, 250), rng.randf_range(-250, 50))
		w.spawn_ball(p, Vector2.ZERO, 5.0)
	for k: int in 40:
		w.spawn_ball(Vector2(150.0 + rng.randf_range(-1, 1), -200.0 + 9.5 * k), Vector2.ZERO, 5.0)
	w.build_grid()
	return w


## Sorted "i,j" (i < j) of every pair closer than the sum of radii.
func _brute_pairs(pos: PackedVector2Array, rad: PackedFloat32Array) -> PackedStringArray:
	var out := PackedStringArray()
	for i: int in pos.size():
		for j: int in range(i + 1, pos.size()):
			if pos[i].distance_squared_to(pos[j]) < (rad[i] + rad[j]) ** 2:
				out.append("%d,%d" % [i, j])
	out.sort()
	return out


## "missing M, extra E": pairs brute force has that the broad phase did not list, and the
## other way round (duplicates count as extra).
func _difference(listed: PackedStringArray, expected: PackedStringArray) -> String:
	var missing := 0
	for pair: String in expected:
		if listed.bsearch(pair) >= listed.size() or listed[listed.bsearch(pair)] != pair:
			missing += 1
	return "missing %d, extra %d" % [missing, listed.size() - (expected.size() - missing)]


func _listed_pairs(w: BallWorld) -> PackedStringArray:
	var pairs: BallPairs = w._pairs
	var t := w.tuning
	pairs.begin(w._balls, t.ball_restitution, t.bounce_threshold, t.rest_speed, Vector2.ZERO)
	pairs.find(w._balls, w._geo, w._lanes, false)
	var out := PackedStringArray()
	for s: int in pairs.stripe_pairs.size():
		var list: PackedInt32Array = pairs.stripe_pairs[s]
		for m: int in range(0, pairs.stripe_used[s], 2):
			out.append("%d,%d" % [mini(list[m], list[m + 1]), maxi(list[m], list[m + 1])])
	out.sort()
	return out


func test_the_broad_phase_lists_exactly_the_touching_pairs() -> void:
	for threads: int in [1, 4]:
		for seed_value: int in [3, 11]:
			var w := _world(threads, seed_value)
			var expected := _brute_pairs(w._balls.pos, w._balls.radius)
			assert_gt(expected.size(), 100, "the heap has touching pairs")
			var what := "%d threads, seed %d" % [threads, seed_value]
			assert_eq(_difference(_listed_pairs(w), expected), "missing 0, extra 0", what)


func test_after_steps_the_keys_kept_in_sorted_order_still_give_exactly_the_touching_pairs() -> void:
	# After a step the keys wait in last step's sorted order (BallStore.cell_keys): each moved
	# ball's is rewritten in place, and a sleeper's stays where it is. While a heap settles,
	# some balls sleep and others move; the broad phase must find the same pairs as brute
	# force at every check.
	for threads: int in [1, 4]:
		var w := _world(threads, 7)
		var mixed := 0
		for check: int in 10:
			for _s: int in 40:
				w.step(1.0 / 240.0)
			if check < 5:
				continue  # the heap is still falling: nothing sleeps yet
			assert_true(w._balls.keys_valid, "the keys were kept, not binned again")
			var sleepers: int = w._balls.asleep.size() - w._balls.asleep.count(0)
			if sleepers > 20 and w._balls.asleep.count(0) > 20:
				mixed += 1
			var expected := _brute_pairs(w._balls.pos, w._balls.radius)
			var what := "%d threads, check %d (%d asleep)" % [threads, check, sleepers]
			assert_eq(_difference(_listed_pairs(w), expected), "missing 0, extra 0", what)
		assert_gt(mixed, 0, "some checks had sleepers and moving balls at once")
