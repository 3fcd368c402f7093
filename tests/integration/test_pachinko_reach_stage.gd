extends GutTest
## The reach and the jackpot on screen (issue 41): a reach brings the reels to the middle of
## the board with numbers at least 80 px tall at 1280 × 720 and slows the game's clock
## while the last reel turns; the jackpot's rounds are announced and its end says what it
## paid; the rising tone, the fanfare and the round bell play.

const GAME := "res://scenes/pachinko/pachinko_game.tscn"
## A digit of the fallback font is this share of its font size tall (measured on the
## pachinko_reach shot: 156 px type, digits 109 px from top to bottom).
const DIGIT_SHARE := 0.7
const FRAME := 1.0 / 60.0
const StretchedWindow := preload("res://tests/integration/stretched_window.gd")


class RecordingBank:
	extends SoundBank
	var heard: Array[StringName] = []

	func play(sound: StringName, _volume_db: float = 0.0, _pitch: float = 1.0) -> bool:
		heard.append(sound)
		return true


func after_each() -> void:
	App.request_board("pachinko", "res://levels/pachinko/classic.board")


func _fever_game() -> PachinkoGame:
	App.request_board("pachinko", "res://levels/pachinko/fever.board")
	var game := (load(GAME) as PackedScene).instantiate() as PachinkoGame
	add_child_autofree(game)
	return game


func _start_reach(rules: PachinkoRules) -> void:
	rules.bonus.reels.start(PackedInt32Array([3, 3, 1]), 7)
	rules.bonus.reels.advance(ReelSet.STOP_SECONDS[1] + 0.01)


func test_a_reach_takes_the_middle_of_the_board_in_large_numbers() -> void:
	App.request_board("pachinko", "res://levels/pachinko/fever.board")
	var scene: PackedScene = load(GAME)
	var game := await StretchedWindow.open(self, scene, Vector2i(1280, 720), 2) as PachinkoGame
	var stage: ReachStage = game.bonus_view().stage
	assert_false(stage.is_on_stage(), "no reach yet")
	_start_reach(game.rules)
	assert_true(game.rules.bonus.reels.in_reach())
	stage._process(1.0)
	assert_true(stage.is_on_stage())
	var screen_scale := (
		stage.get_global_transform_with_canvas().get_scale().y
		* stage.get_viewport().get_final_transform().get_scale().y
	)
	var digit := ReachStage.SYMBOL_FONT_SIZE * DIGIT_SHARE * screen_scale
	assert_gte(digit, 80.0, "reel numbers %.0f px tall on screen" % digit)
	var level := game.rules.level
	assert_eq(stage.center().x, level.ring_center.x, "on the board's middle line")
	game.rules.bonus.reels.advance(ReelSet.REACH_EXTRA + 1.0)
	stage._process(ReachStage.HOLD_MISS + ReachStage.GROW_SECONDS + 0.1)
	stage._process(ReachStage.GROW_SECONDS + 0.1)
	assert_false(stage.is_on_stage(), "gone once the last reel stopped and the moment passed")
	game.free()  # before its window, whose last size change it would answer


# A play trial: "REACH!" covered half the board. The stage now stands inside the ring, covers
# none of the pockets, start pockets or attackers being played for (a tulip may sit under it:
# Hanami has no room between its upper two), and at most a quarter of the ring.
func test_the_reach_stage_leaves_the_pockets_and_most_of_the_board_in_view() -> void:
	for board in ["fever", "hanami", "tulips", "windmills", "classic"]:
		var level := BoardLoader.load_board("res://levels/pachinko/%s.board" % board).level
		if not BonusGeometry.has_reels(level):
			continue
		var stage := ReachStage.new()
		add_child_autofree(stage)
		stage.bind(level, BonusMachine.new(level, BoardWorldFactory.build(level), 1))
		var rect := stage.stage_rect()
		for corner: Vector2 in [rect.position, rect.end, Vector2(rect.end.x, rect.position.y)]:
			var inside := corner.distance_to(level.ring_center) < level.ring_radius
			assert_true(inside, "%s: the stage %s stays inside the ring" % [board, rect])
		var pieces: Array[PocketSpec] = []
		pieces.append_array(level.pockets)
		for spec in level.bonus_pockets:
			if spec.role != BonusPocketSpec.Role.TULIP:
				pieces.append(spec)
		for piece in pieces:
			var mouth := Rect2(
				piece.position - Vector2(piece.width, piece.depth) * 0.5,
				Vector2(piece.width, piece.depth)
			)
			assert_false(
				rect.intersects(mouth),
				"%s: the stage %s covers a pocket at %s" % [board, rect, piece.position]
			)
		var share := rect.get_area() / (PI * level.ring_radius * level.ring_radius)
		assert_lte(share, 0.25, "%s: the stage covers %.0f%% of the ring" % [board, share * 100.0])


# Trial 5: the REACH! box still covered the middle of the board, pins and falling balls.
# It stands in the top part now (over the reels' own window, its bottom above the ring's
# centre); trial 7 saw balls drawn across its reels, so it is drawn over them now.
func test_the_reach_stage_keeps_to_the_top_over_the_balls() -> void:
	for board in ["fever", "hanami"]:
		var level := BoardLoader.load_board("res://levels/pachinko/%s.board" % board).level
		var rect := ReachStage._rect_at(ReachStage.place_on(level))
		assert_lt(
			rect.end.y, level.ring_center.y, "%s: the stage %s in the top half" % [board, rect]
		)
		var reels := BonusGeometry.reel_window(level)
		assert_true(rect.encloses(reels), "%s: over the reels' own window %s" % [board, reels])
	var game := _fever_game()
	await wait_process_frames(1)
	var stage := game.bonus_view().stage
	var balls := game.board_view.get_node("Balls") as Node2D
	# trial 7: balls crossed the big reels; up at the top few balls fly behind it
	assert_gt(stage.z_index, balls.z_index, "the stage is drawn over the balls")


func test_a_reach_slows_the_game_clock_and_gives_it_back() -> void:
	var game := _fever_game()
	var view := game.bonus_view()
	assert_eq(view.time_scale(FRAME), 1.0, "full speed with no reach")
	_start_reach(game.rules)
	var scale := 1.0
	for i in 60:
		scale = view.time_scale(FRAME)
	assert_almost_eq(scale, ReachSlowMotion.SLOW_SCALE, 1e-6, "slow while the last reel turns")
	game.rules.bonus.reels.advance(ReelSet.REACH_EXTRA + 1.0)
	for i in 60:
		scale = view.time_scale(FRAME)
	assert_eq(scale, 1.0, "back to full speed")


func test_reach_and_jackpot_sound_and_announce_their_rounds() -> void:
	var game := _fever_game()
	var view := game.bonus_view()
	var bank := RecordingBank.new()
	add_child_autofree(bank)
	view.use_sounds(bank)
	var machine := game.rules.bonus
	machine.reels.start(PackedInt32Array([2, 2, 2]), 7)
	for i in 300:
		machine.advance(FRAME)
	assert_has(bank.heard, SoundBank.REACH_RISE, "the reach rises")
	assert_has(bank.heard, SoundBank.JACKPOT_FANFARE, "the jackpot's fanfare")
	var banner := view.banner
	assert_string_contains(banner.caption(), "ROUND 1 / %d" % JackpotRounds.ROUNDS)
	machine.rounds.end_round()
	machine.advance(JackpotRounds.BREAK_SECONDS + 0.01)
	assert_string_contains(banner.caption(), "ROUND 2 / %d" % JackpotRounds.ROUNDS)
	assert_has(bank.heard, SoundBank.ROUND_BELL)
	machine.rounds.paid = 150
	machine.rounds.current_round = JackpotRounds.ROUNDS
	machine.rounds.end_round()
	assert_string_contains(banner.caption(), "+150 BALLS")
	assert_string_contains(banner.caption(), "%d rounds played" % JackpotRounds.ROUNDS)
	assert_string_contains(banner.caption(), "balls paid back", "with the game's total")


# A play trial: the ROUND caption was clipped under the rim and the aim's dots were drawn
# over it. Now it sits inside the ring's inner edge on a plaque over everything on the
# board, and the dots hide while a jackpot or round banner (or the reach stage) is up.
func test_the_round_caption_sits_inside_the_ring_over_everything_and_hides_the_aim() -> void:
	var game := _fever_game()
	await wait_process_frames(1)
	var rules := game.rules
	var level := rules.level
	rules.start_game()
	rules.bonus.rounds.begin()
	var fever := game.bonus_view().fever
	assert_string_contains(fever.caption(), "ROUND 1")
	var plaque := fever.caption_rect()
	var inner := level.ring_radius - FeverGlow.RING_WIDTH
	for corner: Vector2 in [
		plaque.position,
		plaque.end,
		Vector2(plaque.end.x, plaque.position.y),
		Vector2(plaque.position.x, plaque.end.y)
	]:
		assert_lt(
			corner.distance_to(level.ring_center), inner, "the caption %s inside the rim" % plaque
		)
	var aim := game.board_view.aim_preview()
	assert_gt(fever.plaque().z_index, aim.z_index, "drawn over the aim's dots")
	assert_gt(fever.plaque().z_index, game.board_view.get_node("Balls").z_index, "and the balls")
	game.bonus_view().banner.show_round(
		level.ring_center, level.ring_radius, 2, JackpotRounds.ROUNDS
	)
	rules.begin_charge()
	rules.set_power(50.0)
	game._process(FRAME)
	aim._process(1.0)
	assert_false(aim.is_showing(), "no aim dots while the round banner is up")
	game.bonus_view().banner._process(10.0)
	game._process(FRAME)
	aim._process(1.0)
	assert_true(aim.is_showing(), "back once it has gone")


# Trial 6: "ROUND 1 / 10  10s  10 to catch" lay across the big reels' 3 3 3 just won.
func test_the_round_caption_keeps_clear_of_the_reels_and_the_reach_stage() -> void:
	for path in ["res://levels/pachinko/fever.board", "res://levels/pachinko/hanami.board"]:
		App.request_board("pachinko", path)
		var game := (load(GAME) as PackedScene).instantiate() as PachinkoGame
		add_child_autofree(game)
		await wait_process_frames(1)
		var rules := game.rules
		rules.start_game()
		rules.bonus.rounds.begin()
		var view := game.bonus_view()
		var window := BonusGeometry.reel_window(rules.level)
		assert_false(view.fever.caption_rect().intersects(window), "%s: off the reels" % path)
		view.stage._shown = 1.0  # the stage holding the jackpot's three alike
		var plaque := view.fever.caption_rect()
		var big := view.stage.stage_rect()
		assert_false(plaque.intersects(big), "%s: plaque %s, stage %s" % [path, plaque, big])
		var inner := rules.level.ring_radius - FeverGlow.RING_WIDTH
		assert_lt(plaque.end.distance_to(rules.level.ring_center), inner, "inside the ring")
