extends RefCounted
## The benchmark scenes as plain data, so BallWorld and GodotPhysics2D build the very same
## board: ring, pins, capsule walls, initial balls, step rate, and the per-scene harness
## rules (respawn, relaunch, tilt). Deterministic: everything comes from seeded RNGs.

const RING_R := 500.0
const BALL_R := 5.0
const PIN_R := 1.5
## Pins fill the band between these heights (px from the ring centre); the top is the
## spawn area, the bottom bowl is where S1 respawns a ball.
const PIN_TOP := -380.0
const PIN_BOTTOM := 380.0
const RESPAWN_Y := 400.0
const MAZE_COLS := 64
const MAZE_PITCH := 35.0
const MAZE_WALL_R := 5.0
## S5's windmills: how many, blade length and radius, the grid they sit on (px), and the
## fastest blade tip (px/s) of the driven ones.
const WINDMILLS := 40
const WHEEL_LENGTH := 28.0
const WHEEL_BLADE_R := 2.0
const WHEEL_PITCH := 110.0
const WHEEL_TIP_SPEED := 1600.0


## A staggered lattice inside the ring: rows `pitch` apart, odd rows shifted half a pitch.
static func pin_lattice(pitch: float) -> PackedVector2Array:
	var pins := PackedVector2Array()
	var row := 0
	var y := PIN_TOP
	while y <= PIN_BOTTOM:
		var x0: float = -RING_R + (pitch * 0.5 if row % 2 == 1 else 0.0)
		var x := x0
		while x <= RING_R:
			var p := Vector2(x, y)
			if p.length() < RING_R - 3.0 * BALL_R:
				pins.append(p)
			x += pitch
		y += pitch
		row += 1
	return pins


## A scene dictionary: name, hz, steps, ring (bool), pins, pin_r, walls (pairs), wall_r,
## balls (positions), vels, ball_r, mode ("flow", "pile", "fast", "maze", "windmills": a
## flow through the lattice with WINDMILLS windmills in it, listed in "windmills" as
## [centre, blades, length, blade radius, speed rad/s, free, friction rad/s²]). `ball_r`
## other than BALL_R is for flow scenes only (the pin sweep's balls that fit a 12 px lattice).
static func make(
	name: String, mode: String, pitch: float, balls: int, hz: float, ball_r := BALL_R
) -> Dictionary:
	var rng := RandomNumberGenerator.new()
	rng.seed = hash(name)
	var scene := {
		"name": name,
		"mode": mode,
		"hz": hz,
		"ring": mode != "maze",
		"pins": PackedVector2Array(),
		"pin_r": PIN_R,
		"walls": PackedVector2Array(),
		"wall_r": MAZE_WALL_R,
		"ball_r": ball_r,
		"pos": PackedVector2Array(),
		"vel": PackedVector2Array(),
		"windmills": [],
	}
	if mode == "maze":
		scene["walls"] = maze_walls(rng)
		_spawn_maze(scene, balls, rng)
		return scene
	scene["pins"] = pin_lattice(pitch)
	if mode == "windmills":
		_add_windmills(scene, rng)
	if mode == "pile":
		_spawn_pile(scene, balls, rng)
	else:
		# Start clear of every pin: a ball placed on a pin would count as a tunnel.
		var near := _bin_pins(scene["pins"])
		for _i: int in balls:
			var p: Vector2 = random_in_field(rng) if mode == "fast" else respawn_point(rng, true)
			var tries := 0
			while (
				not (_clear_of(near, p, ball_r) and _clear_of_wheels(scene, p, ball_r))
				and tries < 1000
			):
				tries += 1
				p = random_in_field(rng) if mode == "fast" else respawn_point(rng, true)
			scene["pos"].append(p)
			scene["vel"].append(fast_velocity(rng) if mode == "fast" else Vector2.ZERO)
	return scene


## A spawn point at the top of the ring, or (for the first fill) anywhere above the bowl.
static func respawn_point(rng: RandomNumberGenerator, first_fill := false) -> Vector2:
	var y: float = rng.randf_range(-470.0, -400.0)
	if first_fill:
		y = rng.randf_range(-470.0, RESPAWN_Y - 20.0)
	var half: float = sqrt(maxf(0.0, (RING_R - 30.0) ** 2 - y * y)) * 0.8
	var x: float = rng.randf_range(-half, half)
	# Keep clear of the lattice: balls start halfway between rows.
	return Vector2(x, y)


## S3's balls start in the pin-free caps above and below the pin band: at a 12 px pitch a
## 5 px ball fits nowhere inside the band, so the band is a wall they must never get into.
static func random_in_field(rng: RandomNumberGenerator) -> Vector2:
	var y: float = rng.randf_range(PIN_BOTTOM + 20.0, 470.0)
	if rng.randf() < 0.5:
		y = -y
	var half: float = sqrt(maxf(0.0, (RING_R - 10.0) ** 2 - y * y))
	return Vector2(rng.randf_range(-half, half), y)


static func fast_velocity(rng: RandomNumberGenerator) -> Vector2:
	return Vector2.from_angle(rng.randf() * TAU) * rng.randf_range(2000.0, 4000.0)


## A perfect maze by seeded depth-first search: one capsule per remaining unit edge.
static func maze_walls(rng: RandomNumberGenerator) -> PackedVector2Array:
	var n: int = MAZE_COLS
	var open_e := PackedByteArray()  # wall to the east of cell i is gone
	var open_s := PackedByteArray()  # wall to the south of cell i is gone
	var seen := PackedByteArray()
	open_e.resize(n * n)
	open_s.resize(n * n)
	seen.resize(n * n)
	open_e.fill(0)
	open_s.fill(0)
	seen.fill(0)
	var stack := PackedInt32Array([0])
	seen[0] = 1
	while not stack.is_empty():
		var c: int = stack[stack.size() - 1]
		var cx: int = c % n
		var cy: int = c / n
		var options := PackedInt32Array()
		if cx > 0 and seen[c - 1] == 0:
			options.append(c - 1)
		if cx < n - 1 and seen[c + 1] == 0:
			options.append(c + 1)
		if cy > 0 and seen[c - n] == 0:
			options.append(c - n)
		if cy < n - 1 and seen[c + n] == 0:
			options.append(c + n)
		if options.is_empty():
			stack.resize(stack.size() - 1)
			continue
		var next: int = options[rng.randi_range(0, options.size() - 1)]
		if next == c + 1:
			open_e[c] = 1
		elif next == c - 1:
			open_e[next] = 1
		elif next == c + n:
			open_s[c] = 1
		else:
			open_s[next] = 1
		seen[next] = 1
		stack.append(next)
	var walls := PackedVector2Array()
	var s: float = MAZE_PITCH
	for cy: int in n:
		for cx: int in n:
			var c: int = cy * n + cx
			var x0: float = cx * s
			var y0: float = cy * s
			if cx < n - 1 and open_e[c] == 0:
				walls.append(Vector2(x0 + s, y0))
				walls.append(Vector2(x0 + s, y0 + s))
			if cy < n - 1 and open_s[c] == 0:
				walls.append(Vector2(x0, y0 + s))
				walls.append(Vector2(x0 + s, y0 + s))
	for k: int in n:
		walls.append_array(PackedVector2Array([Vector2(k * s, 0), Vector2((k + 1) * s, 0)]))
		walls.append_array(PackedVector2Array([Vector2(k * s, n * s), Vector2((k + 1) * s, n * s)]))
		walls.append_array(PackedVector2Array([Vector2(0, k * s), Vector2(0, (k + 1) * s)]))
		walls.append_array(PackedVector2Array([Vector2(n * s, k * s), Vector2(n * s, (k + 1) * s)]))
	return walls


## The maze tilt at time t (s): swinging ±15° on both axes at different rates.
static func maze_tilt(t: float) -> Vector2:
	return Vector2(15.0 * sin(t * 1.3), 15.0 * sin(t * 0.9 + 1.0))


static func _spawn_maze(scene: Dictionary, balls: int, rng: RandomNumberGenerator) -> void:
	var cells := PackedInt32Array()
	for c: int in MAZE_COLS * MAZE_COLS:
		cells.append(c)
	for i: int in range(cells.size() - 1, 0, -1):
		var j: int = rng.randi_range(0, i)
		var tmp: int = cells[i]
		cells[i] = cells[j]
		cells[j] = tmp
	for k: int in mini(balls, cells.size()):
		var c: int = cells[k]
		var p := Vector2((c % MAZE_COLS + 0.5) * MAZE_PITCH, (c / MAZE_COLS + 0.5) * MAZE_PITCH)
		scene["pos"].append(p)
		scene["vel"].append(Vector2.ZERO)


## S2: balls packed on a lattice in the lower part of the ring, clear of every pin.
static func _spawn_pile(scene: Dictionary, balls: int, _rng: RandomNumberGenerator) -> void:
	var near := _bin_pins(scene["pins"])
	var y := RING_R - BALL_R - 1.0
	var placed := 0
	var step := 2.0 * BALL_R + 0.5
	while placed < balls and y > -RING_R:
		var x := -RING_R
		while x < RING_R and placed < balls:
			var p := Vector2(x, y)
			if p.length() < RING_R - BALL_R - 1.0 and _clear_of(near, p):
				scene["pos"].append(p)
				scene["vel"].append(Vector2.ZERO)
				placed += 1
			x += step
		y -= step


## S5: WINDMILLS wheels on a grid inside the ring, each in a clearing of the lattice (its
## sweep, a pin and a ball's width); three in four driven at up to WHEEL_TIP_SPEED at the
## tips, either way, one in four free-spinning.
static func _add_windmills(scene: Dictionary, rng: RandomNumberGenerator) -> void:
	var wheels: Array = []
	var reach := WHEEL_LENGTH + WHEEL_BLADE_R
	var y := -330.0
	var row := 0
	while y <= 330.0 and wheels.size() < WINDMILLS:
		var x := -385.0 + (WHEEL_PITCH * 0.5 if row % 2 == 1 else 0.0)
		row += 1
		while x <= 385.0 and wheels.size() < WINDMILLS:
			if Vector2(x, y).length() + reach < RING_R - 4.0 * BALL_R:
				var k := wheels.size()
				var free := k % 4 == 3
				var tip := (
					rng.randf_range(0.3, 1.0) * WHEEL_TIP_SPEED * (1.0 if k % 2 == 0 else -1.0)
				)
				var speed := 0.0 if free else tip / reach
				wheels.append(
					[Vector2(x, y), 3 + k % 4, WHEEL_LENGTH, WHEEL_BLADE_R, speed, free, 6.0]
				)
			x += WHEEL_PITCH
		y += WHEEL_PITCH
	scene["windmills"] = wheels
	var clear := reach + PIN_R + 2.0 * BALL_R + 1.0
	var kept := PackedVector2Array()
	for q: Vector2 in scene["pins"]:
		var free_of_wheels := true
		for wheel: Array in wheels:
			var c: Vector2 = wheel[0]
			if c.distance_to(q) < clear:
				free_of_wheels = false
				break
		if free_of_wheels:
			kept.append(q)
	scene["pins"] = kept


## True when a ball of `ball_r` at `p` is clear of every windmill's sweep.
static func _clear_of_wheels(scene: Dictionary, p: Vector2, ball_r: float) -> bool:
	for wheel: Array in scene["windmills"]:
		var c: Vector2 = wheel[0]
		var reach: float = wheel[2] + wheel[3] + ball_r + 0.5
		if c.distance_squared_to(p) < reach * reach:
			return false
	return true


## Pins binned in 16 px cells, so a candidate spawn point looks at its neighbours only.
static func _bin_pins(pins: PackedVector2Array) -> Dictionary:
	var near := {}
	for q: Vector2 in pins:
		var key := Vector2i(floori(q.x / 16.0), floori(q.y / 16.0))
		if not near.has(key):
			near[key] = PackedVector2Array()
		var list: PackedVector2Array = near[key]
		list.append(q)
	return near


static func _clear_of(near: Dictionary, p: Vector2, ball_r := BALL_R) -> bool:
	var cx: int = floori(p.x / 16.0)
	var cy: int = floori(p.y / 16.0)
	var clear2: float = (PIN_R + ball_r + 0.5) ** 2
	for dy: int in range(-1, 2):
		for dx: int in range(-1, 2):
			var list: PackedVector2Array = near.get(
				Vector2i(cx + dx, cy + dy), PackedVector2Array()
			)
			for q: Vector2 in list:
				if q.distance_squared_to(p) < clear2:
					return false
	return true
