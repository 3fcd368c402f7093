class_name PowerAim
extends RefCounted
## How launch power aims on a board: lone balls fired at set powers, each followed to its
## end. A lone ball's path depends on its power alone (the simulation is deterministic), so
## a fine sweep of power maps power to where balls enter the field and where they end.
## Used by tools/power_sweep.gd and the aiming tests.

## Outcome codes besides a pocket index (0 and up).
const DRAINED := -1
const RETURNED := -2
const TIMED_OUT := -3
## Longest a shot is followed, seconds of game time.
const MAX_SECONDS := 20.0
## Width of the report's power bins.
const BIN := 10.0


## Fires one lone ball at `power` on a fresh game of `level`. Returns entry_x (the x of the
## first pin it touched, NAN when none) and outcome (a pocket index or one of the codes).
static func shoot(level: BoardLevel, power: float) -> Dictionary:
	var board := level.duplicate() as BoardLevel
	board.cup_start_balls = maxi(board.cup_start_balls, 1)
	var rules := PachinkoRules.new(board, 1)
	rules.start_game()
	return _follow(rules, power)


## Sweeps power from 0 to 100 in `step` increments. Returns shots (power, entry_x, outcome),
## bins (per BIN of power: mean entry x and outcome counts), the catch shares per pocket of
## the weakest and strongest fifth of power, and tv_distance between those two (the play
## analysis's measure: which pockets a band's catches land in, the gutter left out).
static func sweep(level: BoardLevel, step: float) -> Dictionary:
	var board := level.duplicate() as BoardLevel
	board.cup_start_balls = 100000
	var rules := PachinkoRules.new(board, 1)
	rules.start_game()
	var shots: Array = []
	var power := 0.0
	while power <= 100.0001:
		var shot := _follow(rules, power)
		shot["power"] = power
		shots.append(shot)
		power += maxf(step, 0.05)
	var weak := _catch_shares(shots, 0.0, 20.0)
	var strong := _catch_shares(shots, 80.0, 100.0001)
	return {
		"board": level.board_id,
		"rail_end_deg": level.rail_end_deg,
		"pockets": level.pockets.size(),
		"shots": shots,
		"bins": _bins(shots),
		"weak_fifth": weak,
		"strong_fifth": strong,
		"tv_distance": snappedf(tv_distance(weak, strong), 0.001),
	}


## Total-variation distance between two outcome share tables (0: the same, 1: disjoint).
static func tv_distance(a: Dictionary, b: Dictionary) -> float:
	var total := 0.0
	var keys: Dictionary = {}
	for k: String in a:
		keys[k] = true
	for k: String in b:
		keys[k] = true
	for k: String in keys:
		var share_a: float = a.get(k, 0.0)
		var share_b: float = b.get(k, 0.0)
		total += absf(share_a - share_b)
	return total * 0.5


## A short table of a sweep for people.
static func describe(report: Dictionary) -> String:
	var lines := PackedStringArray()
	lines.append(
		(
			"%s  rail end %s°  TV(weak fifth, strong fifth) = %s"
			% [report["board"], report["rail_end_deg"], report["tv_distance"]]
		)
	)
	lines.append("power      entry x   outcomes")
	for bin: Dictionary in report["bins"]:
		lines.append(
			"%5.0f-%-5.0f %7s   %s" % [bin["from"], bin["to"], bin["entry_x"], bin["counts"]]
		)
	lines.append("weak fifth:   %s" % report["weak_fifth"])
	lines.append("strong fifth: %s" % report["strong_fifth"])
	return "\n".join(lines)


static func _follow(rules: PachinkoRules, power: float) -> Dictionary:
	var first_pin: Array = [NAN]
	var outcome: Array = [TIMED_OUT]
	var id := rules.fire(power)
	if id < 0:
		return {"entry_x": NAN, "outcome": TIMED_OUT}
	var on_pin := func(ball: int, pin: int, _speed: float) -> void:
		var seen: float = first_pin[0]
		if ball == id and is_nan(seen):
			first_pin[0] = rules.level.pins[pin].x
	var on_won := func(ball: int, pocket: int, _payout: int, _at: Vector2) -> void:
		if ball == id:
			outcome[0] = pocket
	var on_drained := func(ball: int) -> void:
		if ball == id:
			outcome[0] = DRAINED
	var on_returned := func(ball: int) -> void:
		if ball == id:
			outcome[0] = RETURNED
	rules.world.pin_hit.connect(on_pin)
	rules.ball_won.connect(on_won)
	rules.ball_drained.connect(on_drained)
	rules.ball_returned.connect(on_returned)
	for i in int(MAX_SECONDS / rules.step_seconds()):
		rules.step()
		if rules.balls_in_play() == 0:
			break
	rules.world.pin_hit.disconnect(on_pin)
	rules.ball_won.disconnect(on_won)
	rules.ball_drained.disconnect(on_drained)
	rules.ball_returned.disconnect(on_returned)
	return {"entry_x": first_pin[0], "outcome": outcome[0]}


static func _outcome_name(outcome: int) -> String:
	match outcome:
		DRAINED:
			return "gutter"
		RETURNED:
			return "back"
		TIMED_OUT:
			return "stuck"
	return "p%d" % outcome


# Shares per pocket of the catches by shots with power in [from, to).
static func _catch_shares(shots: Array, from: float, to: float) -> Dictionary:
	var counts: Dictionary = {}
	var total := 0
	for shot: Dictionary in shots:
		var outcome: int = shot["outcome"]
		if shot["power"] < from or shot["power"] >= to or outcome < 0:
			continue
		var key := _outcome_name(outcome)
		var so_far: int = counts.get(key, 0)
		counts[key] = so_far + 1
		total += 1
	var shares: Dictionary = {}
	for key: String in counts:
		var count: int = counts[key]
		shares[key] = snappedf(float(count) / float(total), 0.001)
	return shares


static func _bins(shots: Array) -> Array:
	var bins: Array = []
	var from := 0.0
	while from < 100.0:
		var to := from + BIN
		var xs := 0.0
		var n := 0
		var counts: Dictionary = {}
		for shot: Dictionary in shots:
			var p: float = shot["power"]
			if p < from or (p >= to and to < 100.0) or p > to:
				continue
			var outcome: int = shot["outcome"]
			var entry_x: float = shot["entry_x"]
			var key := _outcome_name(outcome)
			var so_far: int = counts.get(key, 0)
			counts[key] = so_far + 1
			if not is_nan(entry_x):
				xs += entry_x
				n += 1
		var mean := "-" if n == 0 else str(roundi(xs / n))
		bins.append({"from": from, "to": to, "entry_x": mean, "counts": counts})
		from = to
	return bins
