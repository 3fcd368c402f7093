extends SceneTree
## How often the last balls' slow motion comes and how long it lasts, measured over whole
## games played headless the way a player holding the handle plays (60 fps frames, the
## game's clock scaled by SlowMotion exactly as scenes/pachinko/pachinko_game.gd does):
##   tools/godot.sh --headless --path . -s res://tools/juice_stats.gd -- [--games=20]
##       [--handle=60] [--board=classic]
## Prints one JSON line per board: games, triggers per game, slow seconds per trigger
## (median, longest) and the share of a game's real time spent slow.

const BOARDS: Array[String] = ["classic", "fever", "hanami", "tulips", "windmills"]
const FRAME := 1.0 / 60.0
## Real seconds a game may last before it is cut short.
const GAME_LIMIT := 300.0


func _initialize() -> void:
	var games := 20
	var handle := 60.0
	var boards := BOARDS.duplicate()
	for arg in OS.get_cmdline_user_args():
		if arg.begins_with("--games="):
			games = int(arg.get_slice("=", 1))
		elif arg.begins_with("--handle="):
			handle = float(arg.get_slice("=", 1))
		elif arg.begins_with("--board="):
			boards = [arg.get_slice("=", 1)]
	for board in boards:
		var level := BoardLoader.load_board("res://levels/pachinko/%s.board" % board).level
		if level == null:
			printerr("juice_stats: no board '%s'" % board)
			continue
		print(JSON.stringify(_measure(level, games, handle)))
	quit()


func _measure(level: BoardLevel, games: int, handle: float) -> Dictionary:
	var triggers := 0
	var holds := PackedFloat32Array()
	var real_seconds := 0.0
	var slow_seconds := 0.0
	var games_with_slow := 0
	for game in games:
		var rules := PachinkoRules.new(level, game + 1)
		var slow := SlowMotion.new()
		slow.bind(rules)
		rules.start_game()
		rules.handle.set_power(handle)
		rules.handle.grip()
		var hold := 0.0
		var before := slow.triggers
		var clock := 0.0
		while rules.state == PachinkoRules.State.PLAYING and clock < GAME_LIMIT:
			var factor := slow.update(rules, FRAME)
			if factor < 1.0:
				hold += FRAME
				slow_seconds += FRAME
			elif hold > 0.0:
				holds.append(hold)
				hold = 0.0
			rules.advance(FRAME * factor)
			clock += FRAME
		if hold > 0.0:
			holds.append(hold)
		real_seconds += clock
		triggers += slow.triggers - before
		games_with_slow += 1 if slow.triggers > before else 0
		slow.free()
	holds.sort()
	return {
		"board": level.board_id,
		"games": games,
		"handle": handle,
		"triggers_per_game": snappedf(float(triggers) / maxf(games, 1), 0.01),
		"games_with_slow_motion": games_with_slow,
		"slow_seconds_median": snappedf(holds[holds.size() / 2], 0.01) if holds.size() > 0 else 0.0,
		"slow_seconds_longest":
		snappedf(holds[holds.size() - 1], 0.01) if holds.size() > 0 else 0.0,
		"game_seconds_mean": snappedf(real_seconds / maxf(games, 1), 0.1),
		"share_of_time_slow": snappedf(slow_seconds / maxf(real_seconds, 0.001), 0.001),
	}
