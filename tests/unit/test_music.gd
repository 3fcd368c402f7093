extends GutTest
## Music (issue 41): one synthesised loop per machine, in three moods (normal, reach,
## jackpot), built once on a worker thread, played on the Music bus, and turned by the bonus
## machine: a reach, a jackpot, and back.

const FEVER := "res://levels/pachinko/fever.board"


func _rms(samples: PackedFloat32Array) -> float:
	var sum := 0.0
	for value in samples:
		sum += value * value
	return sqrt(sum / maxf(samples.size(), 1.0))


func test_every_machine_has_a_tune_of_its_own() -> void:
	var seen := {}
	for machine in FasciaNames.NAMES:
		assert_true(MusicRecipes.machines().has(machine), "%s has its own tune" % machine)
		var samples := MusicRecipes.render(machine, MusicRecipes.NORMAL)
		var seconds := samples.size() / float(MusicRecipes.RATE)
		assert_almost_eq(seconds, MusicRecipes.loop_seconds(machine, MusicRecipes.NORMAL), 0.01)
		assert_between(seconds, 5.0, 14.0, "%s: a loop of a few bars" % machine)
		assert_gt(_rms(samples), 0.05, "%s: not silent" % machine)
		seen[samples.slice(22050, 22150)] = machine
	assert_eq(seen.size(), FasciaNames.NAMES.size(), "five different tunes")


func test_reach_and_jackpot_are_faster_and_louder() -> void:
	var normal := MusicRecipes.render("classic", MusicRecipes.NORMAL)
	var reach := MusicRecipes.render("classic", MusicRecipes.REACH)
	var jackpot := MusicRecipes.render("classic", MusicRecipes.JACKPOT)
	assert_lt(reach.size(), normal.size(), "a reach picks up the tempo")
	assert_lt(jackpot.size(), reach.size(), "a jackpot more")
	assert_gt(_rms(reach), _rms(normal), "and it builds")
	assert_gt(_rms(jackpot), _rms(normal))


func test_a_loop_plays_seamlessly_forever() -> void:
	var stream := MusicRecipes.build("sakura", MusicRecipes.NORMAL)
	assert_eq(stream.loop_mode, AudioStreamWAV.LOOP_FORWARD)
	assert_eq(stream.loop_begin, 0)
	assert_eq(stream.loop_end, MusicRecipes.render("sakura", MusicRecipes.NORMAL).size())
	assert_eq(stream.format, AudioStreamWAV.FORMAT_16_BITS)


func test_the_bank_builds_a_machine_once_off_the_main_thread() -> void:
	MusicBank.request("country")
	assert_true(MusicBank.is_requested("country"))
	MusicBank.wait_for_background()
	for mood in MusicRecipes.MOODS:
		assert_not_null(MusicBank.loop("country", mood), "country %s built" % mood)
	var first := MusicBank.loop("country", MusicRecipes.NORMAL)
	MusicBank.request("country")
	MusicBank.wait_for_background()
	assert_same(MusicBank.loop("country", MusicRecipes.NORMAL), first, "built once")


func test_a_player_plays_the_loop_on_the_music_bus_and_fades_to_a_new_mood() -> void:
	var player := MusicPlayer.new()
	player.enabled = true  # headless runs build nothing unless asked
	add_child_autofree(player)
	player.play_machine("neon")
	assert_false(MusicBank.is_requested("neon"), "the board's loading goes first")
	player._process(MusicPlayer.BUILD_DELAY + 0.1)
	player._process(0.0)
	assert_true(MusicBank.is_requested("neon"), "then the loops build")
	MusicBank.wait_for_background()
	player._process(0.0)
	assert_same(player.playing_stream(), MusicBank.loop("neon", MusicRecipes.NORMAL))
	assert_eq(player.get_child(0).get("bus"), &"Music")
	player.set_mood(MusicRecipes.JACKPOT)
	player._process(0.0)
	assert_same(player.playing_stream(), MusicBank.loop("neon", MusicRecipes.JACKPOT))


func test_headless_builds_and_plays_nothing() -> void:
	var player := MusicPlayer.new()
	add_child_autofree(player)
	assert_false(player.enabled, "this run is headless")
	player.play_machine("garden")
	assert_false(MusicBank.is_requested("garden"), "no synthesis in a headless run")
	assert_null(player.playing_stream())


func test_an_unknown_mood_is_refused_by_name() -> void:
	var player := MusicPlayer.new()
	add_child_autofree(player)
	player.set_mood(&"disco")
	assert_push_error("no mood 'disco'")
	assert_eq(player.mood(), MusicRecipes.NORMAL)
	player.play_machine("no_such_machine")
	assert_eq(player.machine(), FasciaNames.CLASSIC, "an unknown machine gets Classic's tune")


func test_the_bonus_machine_turns_the_mood() -> void:
	var rules := PachinkoRules.new(BoardLoader.load_board(FEVER).level, 1)
	var music := PachinkoMusic.new()
	add_child_autofree(music)
	music.bind(rules)
	var bonus := rules.bonus
	bonus.reach_started.emit()
	assert_eq(music.mood(), MusicRecipes.REACH, "two reels match: a reach")
	bonus.reach_ended.emit(false)
	assert_eq(music.mood(), MusicRecipes.NORMAL, "missed: back to normal")
	bonus.reach_started.emit()
	bonus.reach_ended.emit(true)
	assert_eq(music.mood(), MusicRecipes.JACKPOT, "a jackpot")
	bonus.jackpot_round_ended.emit(1, 10)
	bonus.attacker_changed.emit(0, false)
	assert_eq(music.mood(), MusicRecipes.JACKPOT, "between rounds the jackpot music plays on")
	bonus.jackpot_ended.emit(140)
	assert_eq(music.mood(), MusicRecipes.NORMAL, "the jackpot's last round ended: back to normal")


func test_the_game_screen_plays_its_machines_music() -> void:
	App.request_board("pachinko", FEVER)
	var game := (load("res://scenes/pachinko/pachinko_game.tscn") as PackedScene).instantiate()
	add_child_autofree(game)
	App.request_board("pachinko", "res://levels/pachinko/classic.board")
	var music := game.get_node("Music") as MusicPlayer
	assert_eq(music.machine(), "neon", "Fever wears the neon machine")
	assert_eq(music.mood(), MusicRecipes.NORMAL)
