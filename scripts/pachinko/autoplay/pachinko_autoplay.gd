class_name PachinkoAutoplay
extends RefCounted
## Plays pachinko by itself, headless, for `--autoplay=pachinko`: dismisses the
## instructions, fires every loaded ball with a random power after a short random pause
## (or, in handle mode, holds the handle at one strength: a stream of 100 balls a minute),
## starts a new game when one ends, and reports what happened. Same board, seconds, seed
## and mode give the same result.

## Frame length the autoplay feeds the simulation (a 60 fps display).
const FRAME_SECONDS := 1.0 / 60.0
## Pause between shots, seconds: a steady human pace (a real machine fires under two balls
## a second; faster, balls on the rail run into each other and roll back).
const MIN_GAP := 0.6
const MAX_GAP := 1.2


## Plays `level` for `seconds` of game time with random powers from `rng_seed`, or with the
## handle held at `handle_power` (0..100; below 0: single shots), or with `chase` by the
## gold-chasing pilot (GoldChaser: re-aimed whenever a gold pin goes out). Returns shots,
## pocket_hits (per pocket), payouts, drained, balls_left, accounting_ok,
## frames_simulated and more (see the keys). A `recorder` (optional) records the games for a
## replay.
static func run(
	level: BoardLevel,
	seconds: float,
	rng_seed: int,
	recorder: ReplayRecorder = null,
	handle_power: int = -1,
	chase: bool = false
) -> Dictionary:
	if level == null or not level.is_pachinko():
		push_error("PachinkoAutoplay: a pachinko board is needed")
		return {"ok": false, "error": "not a pachinko board"}
	if handle_power > 100:
		push_error("PachinkoAutoplay: the handle's strength is 0 to 100")
		return {"ok": false, "error": "the handle's strength is 0 to 100, got %d" % handle_power}
	var rng := RandomNumberGenerator.new()
	rng.seed = rng_seed
	var rules := PachinkoRules.new(level, rng_seed)
	if recorder != null:
		recorder.attach_pachinko(rules, rng_seed)
	var frames := ceili(maxf(seconds, 0.0) / FRAME_SECONDS)
	var steps := 0
	var games := 1
	var peak_in_play := 0
	var accounting_held := true
	var next_shot := 0.0
	var clock := 0.0
	var use_handle := handle_power >= 0 or chase
	rules.handle.set_power(handle_power)
	rules.start_game()
	var aimed_at := -1  # the gold pins' state when the chaser last aimed
	for frame in frames:
		clock += FRAME_SECONDS
		if rules.state != PachinkoRules.State.PLAYING:
			rules.start_game()
			games += 1
		if chase and aimed_at != GoldChaser.aim_key(rules):
			aimed_at = GoldChaser.aim_key(rules)
			rules.handle.set_power(GoldChaser.strength(rules))
		if use_handle:
			rules.handle.grip()  # held all along (game over lets go; take it again)
		elif rules.loaded and clock >= next_shot:
			rules.fire(rng.randf_range(0.0, 100.0))
			next_shot = clock + rng.randf_range(MIN_GAP, MAX_GAP)
		steps += rules.advance(FRAME_SECONDS)
		if recorder != null:
			recorder.note_frame()
		peak_in_play = maxi(peak_in_play, rules.balls_in_play())
		accounting_held = accounting_held and rules.accounting_ok()
	var stats := rules.stats()
	return {
		"shots": stats["shots"],
		"pocket_hits": stats["pocket_hits"],
		"payouts": stats["payouts"],
		"drained": stats["drained"],
		"returned": stats["returned"],
		"won": stats["won"],
		"nudges": stats["nudges"],
		"balls_left": stats["balls_left"],
		"in_play": stats["in_play"],
		"peak_in_play": peak_in_play,
		"games": games,
		"payout_ratio": stats["payout_ratio"],
		"reel_spins": stats["reel_spins"],
		"jackpots": stats["jackpots"],
		"attacker_paid": stats["attacker_paid"],
		"jackpot_paid": stats["jackpot_paid"],
		"jackpots_finished": stats["jackpots_finished"],
		"tulip_opens": stats["tulip_opens"],
		"gold_pins_out": stats["gold_pins_out"],
		"gold_sets": stats["gold_sets"],
		"mode": _mode(handle_power, chase),
		"accounting_ok": accounting_held and rules.accounting_ok(),
		"frames_simulated": frames,
		"physics_steps": steps,
		"state_hash": rules.world.state_hash(),
	}


static func _mode(handle_power: int, chase: bool) -> String:
	if chase:
		return "gold chase"
	return "handle %d" % handle_power if handle_power >= 0 else "single shots"
