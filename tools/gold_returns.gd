extends SceneTree
## Chasing gold pins against holding one strength, as the autoplay plays the real rules:
## for one board it runs single shots at uniform random power, the handle held at each
## candidate strength (GoldChaser.held_best, the strength the board's PinReach says pays
## most, and any given with --held=A,B), and the gold-chasing pilot (GoldChaser), each for
## --seconds of play over seeds 1..--seeds, and prints one JSON line of payout ratios.
##   tools/godot.sh --headless --path . -s res://tools/gold_returns.gd -- --board=fever
##   [--seconds=600] [--seeds=3] [--held=64,2]


func _initialize() -> void:
	var args := {"board": "classic", "seconds": "600", "seeds": "3", "held": ""}
	for arg in OS.get_cmdline_user_args():
		var parts := arg.trim_prefix("--").split("=", true, 1)
		args[parts[0]] = parts[1] if parts.size() > 1 else "yes"
	var loaded := BoardLoader.load_board("res://levels/pachinko/%s.board" % args["board"])
	if loaded.level == null:
		printerr("gold_returns: %s" % loaded.error)
		quit(2)
		return
	var level := loaded.level
	var seconds := float(args["seconds"])
	var seeds := int(args["seeds"])
	var held: Array[int] = [GoldChaser.held_best(PinReach.of(level))]
	for text: String in str(args["held"]).split(",", false):
		if not held.has(int(text)):
			held.append(int(text))
	var report := {"board": args["board"], "seconds": seconds, "seeds": seeds}
	report["uniform"] = _mean(level, seconds, seeds, -1, false)
	var held_returns := {}
	for strength in held:
		held_returns[str(strength)] = _mean(level, seconds, seeds, strength, false)
	report["held"] = held_returns
	report["chase"] = _mean(level, seconds, seeds, -1, true)
	print(JSON.stringify(report))
	quit(0)


func _mean(level: BoardLevel, seconds: float, seeds: int, handle: int, chase: bool) -> Dictionary:
	var ratios: Array[float] = []
	var total := 0.0
	var gold := 0
	for s in range(1, seeds + 1):
		var run := PachinkoAutoplay.run(level, seconds, s, null, handle, chase)
		var ratio: float = run["payout_ratio"]
		ratios.append(ratio)
		total += ratio
		gold += int(run["gold_sets"])
	return {"mean": snappedf(total / maxf(seeds, 1), 0.001), "runs": ratios, "gold_sets": gold}
