extends GutTest
## BallPairs' broad phase against brute force: the pairs it lists over all stripes are
## exactly the touching pairs of the balls, each once, for mixed radii, crowded and lone
## balls, balls on stripe and row edges, and one lane or several.

const BallPairs := preload("res://scripts/physics/ball_pairs.gd")


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
			assert_eq(_listed_pairs(w), expected, "%d threads, seed %d" % [threads, seed_value])
