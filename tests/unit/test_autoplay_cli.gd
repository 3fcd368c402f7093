extends GutTest
## The command-line autoplay arguments: good ones parse, odd ones get a clear error.

const AutoplayCli := preload("res://scripts/app/autoplay_cli.gd")


func test_full_pachinko_line_parses() -> void:
	var args := PackedStringArray(
		["--autoplay=pachinko", "--board=classic", "--seconds=60", "--seed=7"]
	)
	var options := AutoplayCli.parse(args)
	assert_false(options.has("error"), str(options))
	assert_eq(options["game"], "pachinko")
	assert_eq(options["board"], "classic")
	assert_eq(options["seconds"], 60.0)
	assert_eq(options["seed"], 7)


func test_seconds_default_per_game() -> void:
	assert_eq(AutoplayCli.parse(PackedStringArray(["--autoplay=maze"]))["seconds"], 120.0)
	assert_eq(AutoplayCli.parse(PackedStringArray(["--autoplay=pachinko"]))["seconds"], 60.0)


func test_unknown_game_is_named_in_the_error() -> void:
	var options := AutoplayCli.parse(PackedStringArray(["--autoplay=pinball"]))
	assert_string_contains(str(options.get("error", "")), "pinball")


func test_bad_numbers_are_refused() -> void:
	for bad: String in ["--seconds=abc", "--seconds=-5", "--seconds=0", "--seconds=1e9"]:
		var options := AutoplayCli.parse(PackedStringArray(["--autoplay=maze", bad]))
		assert_true(options.has("error"), "%s should be refused" % bad)
	var seeded := AutoplayCli.parse(PackedStringArray(["--autoplay=maze", "--seed=x"]))
	assert_string_contains(str(seeded.get("error", "")), "--seed")


func test_unknown_argument_is_refused() -> void:
	var options := AutoplayCli.parse(PackedStringArray(["--autoplay=maze", "--fast"]))
	assert_string_contains(str(options.get("error", "")), "--fast")


func test_wants_autoplay_only_when_asked() -> void:
	assert_true(AutoplayCli.wants_autoplay(PackedStringArray(["--autoplay=maze"])))
	assert_false(AutoplayCli.wants_autoplay(PackedStringArray(["--board=classic"])))


func test_board_names_resolve_to_level_files() -> void:
	assert_eq(AutoplayCli.resolve_board_path("maze", "classic"), "res://levels/maze/classic.tres")
	assert_eq(AutoplayCli.resolve_board_path("pachinko", "res://x/y.tres"), "res://x/y.tres")
