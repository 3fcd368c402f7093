extends SceneTree
## Measures what a jackpot pays at the autoplay's single-shot pace, many jackpots quickly:
## for each seed it plays 20 s of a game on the board (a full field), then gives it a
## jackpot (the reels' result forced to three alike) and plays on at the same pace until
## the jackpot's last round ends. A natural jackpot comes about four times an hour, so
## sampling 20 of them through --sessions takes hours of play; this takes minutes. Prints
## one JSON line: jackpots, mean, min, max and each payout.
##   tools/godot.sh --headless --path . -s res://tools/jackpot_sample.gd -- --board=fever --count=25

const WARM_UP := 20.0
const MOST_SECONDS := 600.0


func _initialize() -> void:
	var board := "fever"
	var count := 25
	for arg in OS.get_cmdline_user_args():
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
	for game_seed in range(1, count + 1):
		payouts.append(_one(level, game_seed))
	var total := 0
	for paid in payouts:
		total += paid
	var report := {
		"board": level.board_id,
		"jackpots": payouts.size(),
		"mean": snappedf(float(total) / maxi(payouts.size(), 1), 0.1),
		"min": payouts.min(),
		"max": payouts.max(),
		"payouts": payouts,
	}
	print(JSON.stringify(report))
	quit(0)


func _one(level: BoardLevel, game_seed: int) -> int:
	var rng := RandomNumberGenerator.new()
	rng.seed = game_seed
	var rules := PachinkoRules.new(level, game_seed)
	var paid := [-1]
	rules.bonus.jackpot_ended.connect(func(balls: int) -> void: paid[0] = balls)
	rules.start_game()
	var clock := 0.0
	var next_shot := 0.0
	var forced := false
	while paid[0] < 0 and clock < MOST_SECONDS:
		clock += PachinkoAutoplay.FRAME_SECONDS
		if not forced and clock >= WARM_UP and not rules.bonus.reels.busy():
			rules.bonus._on_spin_finished(PackedInt32Array([0, 0, 0]), true)
			forced = true
		if rules.loaded and clock >= next_shot:
			rules.fire(rng.randf_range(0.0, 100.0))
			next_shot = clock + rng.randf_range(PachinkoAutoplay.MIN_GAP, PachinkoAutoplay.MAX_GAP)
		rules.advance(PachinkoAutoplay.FRAME_SECONDS)
	return maxi(paid[0], 0)
