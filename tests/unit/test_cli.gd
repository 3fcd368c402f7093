extends GutTest
## The command line: every user argument is checked against the one flag table; a bad one is
## named in the error and exits 2 before the game starts; --help lists every flag.


class TestGoodArguments:
	extends GutTest

	func test_full_autoplay_line_parses_to_typed_values() -> void:
		var parsed := CliParser.parse(
			PackedStringArray(
				["--autoplay=pachinko", "--board=classic", "--seconds=60", "--seed=7", "--hard"]
			)
		)
		assert_eq(parsed.error, "")
		assert_eq(parsed.command, "--autoplay")
		assert_eq(
			parsed.values,
			{
				"autoplay": "pachinko",
				"board": "classic",
				"seconds": 60.0,
				"seed": 7,
				"hard": true,
				"handle": -1,
				"chase": false
			}
		)
		assert_typeof(parsed.values["seconds"], TYPE_FLOAT)
		assert_typeof(parsed.values["seed"], TYPE_INT)

	func test_missing_options_take_the_table_defaults() -> void:
		var parsed := CliParser.parse(PackedStringArray(["--autoplay=maze"]))
		assert_eq(parsed.error, "")
		assert_eq(
			parsed.values,
			{
				"autoplay": "maze",
				"board": "classic",
				"seed": 1,
				"hard": false,
				"handle": -1,
				"chase": false
			}
		)

	func test_no_arguments_means_the_normal_game() -> void:
		var parsed := CliParser.parse(PackedStringArray())
		assert_eq(parsed.error, "")
		assert_eq(parsed.command, "")
		assert_eq(CommandLine.run(PackedStringArray()), CommandLine.START_GAME)

	func test_help_wins_over_other_good_flags() -> void:
		assert_eq(
			CliParser.parse(PackedStringArray(["--autoplay=maze", "--help"])).command, "--help"
		)


class TestBadArguments:
	extends GutTest

	# Each bad line, and a piece the error must contain to name what is wrong.
	const CASES := [
		[["--optimise=pachinko"], "unknown flag '--optimise'"],
		[["--analyze=pinball"], "got 'pinball'"],
		[["--analyze=pachinko", "--shots=many"], "--shots must be a whole number"],
		[["--autoplay=maze", "--fast"], "unknown flag '--fast'"],
		[["--autoplya=maze"], "did you mean --autoplay?"],
		[["--autoplay=pinball"], "got 'pinball'"],
		[["--autoplay=maze", "--seconds=abc"], "--seconds must be a number"],
		[["--autoplay=maze", "--seconds=-5"], "--seconds"],
		[["--autoplay=maze", "--seconds=0"], "--seconds"],
		[["--autoplay=maze", "--seconds=1e9"], "--seconds"],
		[["--autoplay=maze", "--seed=x"], "--seed must be a whole number, got 'x'"],
		[["--autoplay=maze", "--seed"], "--seed needs a value: --seed=N"],
		[["--autoplay=maze", "--board="], "--board needs a value"],
		[["--autoplay=maze", "--hard=yes"], "--hard takes no value"],
		[["--autoplay=maze", "--seed=1", "--seed=2"], "--seed is given twice"],
		[["--board=classic"], "--board needs a command to go with: --autoplay"],
		[["--autoplay=maze", "classic"], "'classic' is not a flag"],
		[["-x"], "'-x' is not a flag"],
		[["--"], "'--' is not a flag"],
		[["--help", "--bogus"], "unknown flag '--bogus'"],
	]

	func test_each_bad_line_is_refused_naming_the_problem() -> void:
		for case: Array in CASES:
			var parsed := CliParser.parse(PackedStringArray(case[0]))
			assert_string_contains(parsed.error, str(case[1]), "for %s" % [case[0]])
			assert_eq(parsed.command, "", "a refused line runs nothing: %s" % [case[0]])

	func test_a_far_miss_gets_no_guess() -> void:
		assert_false(CliParser.parse(PackedStringArray(["--zzz"])).error.contains("did you mean"))

	func test_bad_flags_exit_2_without_running_anything() -> void:
		var code := CommandLine.run(PackedStringArray(["--optimise=pachinko"]))
		assert_eq(code, CliFlags.EXIT_USAGE)
		assert_eq(code, 2)


class TestFlagTable:
	extends GutTest

	func test_every_row_is_complete() -> void:
		for row: Dictionary in CliFlags.FLAGS:
			var flag := str(row["flag"])
			assert_true(flag.begins_with("--"), flag)
			assert_false(str(row.get("help", "")).is_empty(), "%s has help" % flag)
			assert_true(str(row.get("example", "")).contains(flag), "%s example uses it" % flag)
			if row.get("command", false):
				assert_true(flag == "--help" or row.get("runs") is Script, "%s runs" % flag)
			else:
				assert_false((row.get("for", []) as Array).is_empty(), "%s names commands" % flag)

	func test_every_example_parses_cleanly() -> void:
		for row: Dictionary in CliFlags.FLAGS:
			var example := str(row["example"]).split(" ")
			assert_eq(CliParser.parse(example).error, "", "example of %s" % row["flag"])


class TestHelp:
	extends GutTest

	func test_help_lists_every_flag_with_its_example() -> void:
		var text := CliHelp.text()
		for row: Dictionary in CliFlags.FLAGS:
			assert_string_contains(text, CliFlags.usage_of(row))
			assert_string_contains(text, "e.g. -- %s" % row["example"])

	func test_help_fits_in_100_columns() -> void:
		for line in CliHelp.text().split("\n"):
			assert_lt(line.length(), 100, line)

	func test_help_exits_0() -> void:
		assert_eq(CommandLine.run(PackedStringArray(["--help"])), CliFlags.EXIT_OK)
