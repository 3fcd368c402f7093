extends RefCounted
## Screenshot states for the game screen (tools/shots calls the scene's prepare_shot):
## "pachinko_start" the instructions, "pachinko_play" many balls in play with the flipper
## drawn back, "pachinko_win" the moment a pocket pays out, "pachinko_over" game over.
## Each plays the real rules forward at 60 fps; nothing is faked.

const FRAME := 1.0 / 60.0


## Plays `rules` into the state named `shot_name`.
static func prepare(rules: PachinkoRules, shot_name: String) -> void:
	match shot_name:
		"pachinko_play":
			_play(rules)
		"pachinko_win":
			_win(rules)
		"pachinko_over":
			_over(rules)


static func _play(rules: PachinkoRules) -> void:
	rules.start_game()
	for frame in 60 * 4:
		if rules.loaded and frame % 8 == 0:
			rules.fire(20.0 + float(frame * 53 % 80))
		rules.advance(FRAME)
	rules.press_flipper(Vector2(0, 100))
	rules.drag_to(Vector2(0, 35))


static func _win(rules: PachinkoRules) -> void:
	rules.start_game()
	var won := [false]
	var mark := func(_id: int, _p: int, _n: int, _at: Vector2) -> void: won[0] = true
	rules.ball_won.connect(mark)
	for frame in 60 * 90:
		if rules.state != PachinkoRules.State.PLAYING:
			rules.start_game()
		if rules.loaded and frame % 9 == 0:
			rules.fire(30.0 + float(frame * 37 % 70))
		rules.advance(FRAME)
		if won[0]:
			break
	rules.ball_won.disconnect(mark)


static func _over(rules: PachinkoRules) -> void:
	rules.start_game()
	for frame in 60 * 240:
		if rules.state != PachinkoRules.State.PLAYING:
			break
		if rules.loaded and frame % 30 == 0:
			rules.fire(20.0 + float(frame * 53 % 80))
		rules.advance(FRAME)
