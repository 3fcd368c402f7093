extends SceneTree
## Balls per jackpot round by handle power: on each board with an attacker, a jackpot is
## opened at once (its ten rounds) while the handle streams at one power, and the attacker's
## catches are counted. Prints one JSON line per board: power -> catches per round.
##   tools/godot.sh --headless --path . -s res://tools/attacker_band.gd -- --board=fever
##     [--powers=0,10,...] [--seeds=1,2]

const BandArgs := preload("res://tools/band_tool_args.gd")
const MAX_SECONDS := 200.0


func _init() -> void:
	var defaults: Array[int] = []
	for p in range(0, 101, 10):
		defaults.append(p)
	var args := BandArgs.new()
	args.read(OS.get_cmdline_user_args(), "fever", defaults)
	var level := args.load_level("attacker_band")
	if level == null:
		quit(1)
		return
	var board := args.board
	var powers := args.powers
	var seeds := args.seeds
	var per_round := {}
	for power in powers:
		var catches := 0
		var rounds := 0
		for rng_seed in seeds:
			var got := _jackpot_at(level, power, rng_seed)
			catches += got.x
			rounds += got.y
		per_round[power] = snappedf(float(catches) / maxf(rounds, 1), 0.01)
	print(JSON.stringify({"board": board, "seeds": seeds, "catches_per_round": per_round}))
	quit(0)


# x: the attacker's catches during one jackpot streamed at `power`; y: its rounds played.
func _jackpot_at(level: BoardLevel, power: int, rng_seed: int) -> Vector2i:
	var rules := PachinkoRules.new(level, rng_seed)
	rules.start_game()
	rules.cup = 100000
	rules.handle.set_power(power)
	rules.handle.grip()
	rules.bonus.rounds.begin()
	var caught := [0]
	var played := [0]
	rules.bonus.jackpot_round_ended.connect(func(_r: int, _n: int) -> void: played[0] += 1)
	var paid_before := rules.bonus.jackpot_paid
	var steps := int(MAX_SECONDS / rules.step_seconds())
	for i in steps:
		rules.step()
		if not rules.bonus.rounds.active():
			break
	var payout := 1
	for spec in level.bonus_pockets:
		if spec.role == BonusPocketSpec.Role.ATTACKER:
			payout = maxi(spec.payout, 1)
	caught[0] = (rules.bonus.jackpot_paid - paid_before) / payout
	return Vector2i(caught[0], played[0])
