extends SceneTree
## Measures what a jackpot pays at the autoplay's single-shot pace, many jackpots quickly:
## for each seed it plays 20 s of a game on the board (a full field), then gives it a
## jackpot (the reels' result forced to three alike) and plays on at the same pace until
## the jackpot's last round ends. A natural jackpot comes about four times an hour, so
## sampling 20 of them through --sessions takes hours of play; this takes minutes. Prints
## one JSON line: jackpots, mean, min, max and each payout. With --aim the player aims: while
## the rounds last it holds the handle in the middle of the board's attacker band
## (AttackerBands, as the launcher tells a player), a stream of 100 balls a minute, and
## shoots at random between them (trial 8: an aiming player, 714 balls from one jackpot).
## After the jackpot it plays on AFTER seconds and counts a jackpot again (another jackpot
## begun then: the spins queued during the rounds run at once; trial 8 had one).
##   tools/godot.sh --headless --path . -s res://tools/jackpot_sample.gd -- --board=fever --count=25
##   ... -- --board=fever --count=20 --aim

const WARM_UP := 20.0
const MOST_SECONDS := 600.0
## Seconds played after a jackpot's end while a jackpot again is looked for.
const AFTER := 25.0


func _initialize() -> void:
	var board := "fever"
	var count := 25
	var aim := false
	for arg in OS.get_cmdline_user_args():
		if arg == "--aim":
			aim = true
		if arg.begins_with("--board="):
			board = arg.trim_prefix("--board=")
		elif arg.begins_with("--count="):
			count = int(arg.trim_prefix("--count="))
	var level: BoardLevel = BoardLoader.load_board("res://levels/pachinko/%s.board" % board).level
	if level == null:
		printerr("jackpot_sample: no board %s" % board)
		quit(2)
		return
	level = level.duplicate_level()
	level.cup_start_balls = 1000  # the cup never runs dry while a jackpot is measured
	var payouts: Array[int] = []
	var nets: Array[int] = []
	var again := 0
	for game_seed in range(1, count + 1):
		var one := _one(level, game_seed, aim)
		payouts.append(one.x)
		nets.append(one.y)
		again += one.z
	var net_total := 0
	for net in nets:
		net_total += net
	var total := 0
	for paid in payouts:
		total += paid
	var report := {
		"board": level.board_id,
		"aim": aim,
		"jackpots": payouts.size(),
		"mean": snappedf(float(total) / maxi(payouts.size(), 1), 0.1),
		"min": payouts.min(),
		"max": payouts.max(),
		"payouts": payouts,
		"again": again,
		"net_mean": snappedf(float(net_total) / maxi(nets.size(), 1), 0.1),
		"nets": nets,
	}
	print(JSON.stringify(report))
	quit(0)


# One forced jackpot: what it paid (x) and the balls held from its start to its end (y: the
# payout less the balls shot meanwhile, plus what they won elsewhere), and 1 in z when
# another jackpot began within AFTER seconds of its end.
func _one(level: BoardLevel, game_seed: int, aim: bool) -> Vector3i:
	var band := AttackerBands.band_of(level)
	var rng := RandomNumberGenerator.new()
	rng.seed = game_seed
	var rules := PachinkoRules.new(level, game_seed)
	var paid := [-1]
	rules.bonus.jackpot_ended.connect(func(balls: int) -> void: paid[0] = balls)
	rules.start_game()
	var clock := 0.0
	var next_shot := 0.0
	var forced := false
	var held_at_start := 0
	while paid[0] < 0 and clock < MOST_SECONDS:
		clock += PachinkoAutoplay.FRAME_SECONDS
		if not forced and clock >= WARM_UP and not rules.bonus.reels.busy():
			rules.bonus._on_spin_finished(PackedInt32Array([0, 0, 0]), true)
			forced = true
			held_at_start = rules.balls_to_shoot
		if aim and rules.bonus.rounds.active() and band != Vector2i.ZERO:
			rules.handle.set_power((band.x + band.y) * 0.5)
			rules.handle.grip()
		elif rules.handle.held:
			rules.handle.let_go()
		if rules.handle.held:
			pass  # the handle streams
		elif rules.loaded and clock >= next_shot:
			rules.fire(rng.randf_range(0.0, 100.0))
			next_shot = clock + rng.randf_range(PachinkoAutoplay.MIN_GAP, PachinkoAutoplay.MAX_GAP)
		rules.advance(PachinkoAutoplay.FRAME_SECONDS)
	var net := rules.balls_to_shoot - held_at_start
	var end := clock
	var jackpots := rules.bonus.jackpots
	rules.handle.let_go()
	while clock < end + AFTER and rules.bonus.jackpots == jackpots:
		clock += PachinkoAutoplay.FRAME_SECONDS
		if rules.loaded and clock >= next_shot:
			rules.fire(rng.randf_range(0.0, 100.0))
			next_shot = clock + rng.randf_range(PachinkoAutoplay.MIN_GAP, PachinkoAutoplay.MAX_GAP)
		rules.advance(PachinkoAutoplay.FRAME_SECONDS)
	return Vector3i(maxi(paid[0], 0), net, 1 if rules.bonus.jackpots > jackpots else 0)
