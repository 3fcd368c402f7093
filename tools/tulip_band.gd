extends SceneTree
## Which handle strengths reach each tulip while it is open: on a board with tulips, each
## tulip in turn is held open (opened again as soon as a ball shuts it) while the handle
## streams at one strength, and the balls it catches open are counted. Prints one JSON line
## per board: tulip (its bonus pocket index) -> strength -> catches per 100 shots, and the
## band each tulip's catches say (the strengths within half of its best, around the best).
##   tools/godot.sh --headless --path . -s res://tools/tulip_band.gd -- --board=tulips
##     [--powers=30,35,...] [--shots=120] [--seeds=1,2]

const BandArgs := preload("res://tools/band_tool_args.gd")
const MAX_SECONDS := 400.0


func _init() -> void:
	var defaults: Array[int] = []
	for p in range(30, 101, 5):
		defaults.append(p)
	var args := BandArgs.new()
	args.read(OS.get_cmdline_user_args(), "tulips", defaults, 120)
	var level := args.load_level("tulip_band")
	if level == null:
		quit(1)
		return
	var board := args.board
	var powers := args.powers
	var seeds := args.seeds
	var shots := args.shots
	var rates := {}
	var bands := {}
	for i in level.bonus_pockets.size():
		if level.bonus_pockets[i].role != BonusPocketSpec.Role.TULIP:
			continue
		var by_power := {}
		for power in powers:
			var caught := 0
			for rng_seed in seeds:
				caught += _catches_open(level, i, power, shots, rng_seed)
			by_power[power] = snappedf(100.0 * caught / float(shots * seeds.size()), 0.1)
		rates[i] = by_power
		bands[i] = _band(by_power, powers)
	print(JSON.stringify({"board": board, "shots": shots, "per_100_shots": rates, "bands": bands}))
	quit(0)


# The balls tulip `index` caught while open in `shots` shots streamed at `power`.
func _catches_open(level: BoardLevel, index: int, power: int, shots: int, rng_seed: int) -> int:
	var rules := PachinkoRules.new(level, rng_seed)
	rules.start_game()
	rules.cup = 100000
	rules.handle.set_power(power)
	rules.handle.grip()
	var caught := 0
	var steps := int(MAX_SECONDS / rules.step_seconds())
	for step in steps:
		if not rules.bonus.is_open(index):
			rules.bonus.catch(index)  # open it (again): it is the target being measured
		rules.step()
		if not rules.bonus.is_open(index):
			caught += 1  # a ball shut it: caught while open
		if rules.ledger.shots >= shots:
			break
	return caught


# The strengths within half of the best rate, the run around the best.
static func _band(by_power: Dictionary, powers: Array[int]) -> Array[int]:
	var best := powers[0]
	for power in powers:
		if float(by_power[power]) > float(by_power[best]):
			best = power
	var cut := float(by_power[best]) * 0.5
	var low := best
	var high := best
	var at := powers.find(best)
	while at > 0 and float(by_power[powers[at - 1]]) >= cut:
		at -= 1
		low = powers[at]
	at = powers.find(best)
	while at < powers.size() - 1 and float(by_power[powers[at + 1]]) >= cut:
		at += 1
		high = powers[at]
	return [low, high]
