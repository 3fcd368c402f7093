class_name CliFlags
extends RefCounted
## The one table of command-line flags: the user arguments after `--`, as in
## `godot --headless --path . -- --autoplay=maze --seconds=30`.
##
## A row is either a command, which picks what the run does (at most one per run; none plays
## the game), or an option that only works with the commands listed in its `for`. The parser,
## the value checks and `--help` all read this table, so a new flag is one new row, and a new
## command is a row whose `runs` script has `static func run(values: Dictionary) -> int`.
##
## Row keys: `flag`; `command` (true for commands); `value` (a [enum Value]); `choices` for
## [constant Value.CHOICE]; `max` for [constant Value.SECONDS]; `placeholder` shown in help;
## `default` (options only, filled in when the flag is absent); `for` (options only: the
## commands it works with); `runs` (commands only); `help`; `example` (a full argument list).

## What a flag's value must be.
enum Value {
	NONE,  ## a switch: `--hard`, never `--hard=...`
	CHOICE,  ## one of the row's `choices`
	WHOLE,  ## a whole number
	SECONDS,  ## a number of seconds above 0 and at most the row's `max`
	TEXT,  ## any non-empty text
}

## Exit code for a run that did what it was asked.
const EXIT_OK := 0
## Exit code for unknown flags, bad values, or input the command cannot use.
const EXIT_USAGE := 2

const FLAGS: Array[Dictionary] = [
	{
		"flag": "--help",
		"command": true,
		"value": Value.NONE,
		"help": "Print every flag with an example, then exit.",
		"example": "--help",
	},
	{
		"flag": "--autoplay",
		"command": true,
		"value": Value.CHOICE,
		"choices": BoardLevel.KIND_NAMES,
		"placeholder": "GAME",
		"runs": preload("res://scripts/app/autoplay_cli.gd"),
		"help": "Play a game headless by itself and print one JSON line saying what happened.",
		"example": "--autoplay=pachinko --board=classic --seconds=60 --seed=1",
	},
	{
		"flag": "--check-boards",
		"command": true,
		"value": Value.NONE,
		"runs": preload("res://scripts/loading/board_check_cli.gd"),
		"help":
		(
			"Load every board file in levels/ and user://boards/, print one JSON line per file"
			+ " and a summary; exit 1 when any is refused."
		),
		"example": "--check-boards",
	},
	{
		"flag": "--replay",
		"command": true,
		"value": Value.TEXT,
		"placeholder": "FILE",
		"runs": preload("res://scripts/replay/replay_cli.gd"),
		"help":
		(
			"Play a replay file headless on its board and print one JSON line with the final"
			+ " state hash; exit 0 when it matches the recorded one, 1 when not, 2 for a bad"
			+ " file or a missing or changed board."
		),
		"example": "--replay=build/maze.replay",
	},
	{
		"flag": "--analyze",
		"command": true,
		"value": Value.CHOICE,
		"choices": BoardLevel.KIND_NAMES,
		"placeholder": "GAME",
		"runs": preload("res://scripts/app/analyze_cli.gd"),
		"help":
		(
			"Play analysis: fire many shots (pachinko) or play many pilot games (maze), print"
			+ " one JSON line and write it, with a heat-map PNG for pachinko, to --out or to"
			+ " the folder of your saved games (reports/)."
		),
		"example": "--analyze=pachinko --board=classic --shots=10000 --seed=1 --threads=2",
	},
	{
		"flag": "--sessions",
		"command": true,
		"value": Value.WHOLE,
		"placeholder": "N",
		"runs": preload("res://scripts/app/sessions_cli.gd"),
		"help":
		(
			"Pachinko: play N sessions from a full cup to an empty one at the autoplay's"
			+ " single-shot pace (seeds --seed, --seed + 1, ...) and print one JSON line: median"
			+ " and 10th percentile session seconds, jackpots per hour, mean jackpot payout."
		),
		"example": "--sessions=20 --board=fever --seed=1",
	},
	{
		"flag": "--board",
		"for": ["--autoplay", "--analyze", "--sessions"],
		"value": Value.TEXT,
		"placeholder": "ID",
		"default": "classic",
		"help":
		(
			"The board: a name in levels/<game>/, or a res://levels/ or user://boards/ path"
			+ " (default classic)."
		),
		"example": "--autoplay=maze --board=catacombs",
	},
	{
		"flag": "--seconds",
		"for": ["--autoplay"],
		"value": Value.SECONDS,
		"max": 3600.0,
		"placeholder": "S",
		"help": "Game seconds to simulate (default 60 for pachinko, 120 for the maze).",
		"example": "--autoplay=maze --seconds=30",
	},
	{
		"flag": "--seed",
		"for": ["--autoplay", "--analyze", "--sessions"],
		"value": Value.WHOLE,
		"placeholder": "N",
		"default": 1,
		"help": "Random seed: the same seed on the same build plays the same game (default 1).",
		"example": "--autoplay=pachinko --seed=7",
	},
	{
		"flag": "--handle",
		"for": ["--autoplay"],
		"value": Value.WHOLE,
		"placeholder": "POWER",
		"default": -1,
		"help":
		(
			"Pachinko: hold the handle at this strength (0-100) for a stream of 100 balls a"
			+ " minute instead of single shots at random strengths (default: single shots)."
		),
		"example": "--autoplay=pachinko --handle=60",
	},
	{
		"flag": "--chase",
		"for": ["--autoplay"],
		"value": Value.NONE,
		"default": false,
		"help":
		(
			"Pachinko: the gold-chasing pilot holds the handle and turns it to reach the gold"
			+ " pins left (instead of single shots)."
		),
		"example": "--autoplay=pachinko --chase",
	},
	{
		"flag": "--hard",
		"for": ["--autoplay"],
		"value": Value.NONE,
		"default": false,
		"help": "Hard mode: the maze's black holes are live (the pachinko game ignores it).",
		"example": "--autoplay=maze --hard",
	},
	{
		"flag": "--record",
		"for": ["--autoplay"],
		"value": Value.TEXT,
		"placeholder": "FILE",
		"help": "Save the autoplay's game as a replay file (play it with --replay=FILE).",
		"example": "--autoplay=maze --seconds=30 --record=build/maze.replay",
	},
	{
		"flag": "--shots",
		"for": ["--analyze"],
		"value": Value.WHOLE,
		"placeholder": "N",
		"default": 10000,
		"help": "Shots the pachinko analysis fires, at uniform random power (default 10000).",
		"example": "--analyze=pachinko --shots=2000",
	},
	{
		"flag": "--played",
		"for": ["--analyze"],
		"value": Value.NONE,
		"default": false,
		"help":
		(
			"Pachinko: fire the shots as the autoplay plays them, one at a time among the"
			+ " balls in play with ball contacts on (about seven times slower)."
		),
		"example": "--analyze=pachinko --board=classic --played",
	},
	{
		"flag": "--profile",
		"for": ["--analyze"],
		"value": Value.NONE,
		"default": false,
		"help":
		(
			'Pachinko: add a "profile" entry to the report, the seconds each stage of the'
			+ " analysis took (rail climbs, chunk set-up, stepping, samples, tally)."
		),
		"example": "--analyze=pachinko --board=classic --threads=1 --profile",
	},
	{
		"flag": "--tally",
		"for": ["--analyze"],
		"value": Value.TEXT,
		"placeholder": "FILE",
		"help":
		(
			"Pachinko, worker mode (the editor's Analyze runs it): write only the counts to"
			+ " FILE, with FILE.status and FILE.part while it runs; no report, no heat map."
		),
		"example": "--analyze=pachinko --board=classic --tally=/tmp/classic.tally",
	},
	{
		"flag": "--workers",
		"for": ["--analyze"],
		"value": Value.WHOLE,
		"placeholder": "N",
		"help":
		(
			"Pachinko: split the shots over N worker processes of this game, figures"
			+ " unchanged (default: one per core when there are more than 2 cores, else none;"
			+ " 0 runs on threads in this process)."
		),
		"example": "--analyze=pachinko --board=classic --workers=4",
	},
	{
		"flag": "--queue",
		"for": ["--analyze"],
		"value": Value.TEXT,
		"placeholder": "DIR",
		"help":
		(
			"Pachinko, worker mode (--workers starts it): take chunks of shots from the queue"
			+ " folder DIR and write their counts there, until the queue is closed."
		),
		"example": "--analyze=pachinko --board=classic --queue=/tmp/q --worker-id=0",
	},
	{
		"flag": "--worker-id",
		"for": ["--analyze"],
		"value": Value.WHOLE,
		"placeholder": "K",
		"default": 0,
		"help": "With --queue: this worker's number in the queue's file names.",
		"example": "--analyze=pachinko --board=classic --queue=/tmp/q --worker-id=1",
	},
	{
		"flag": "--runs",
		"for": ["--analyze"],
		"value": Value.WHOLE,
		"placeholder": "N",
		"default": 20,
		"help": "Games the maze analysis plays in each of easy and hard mode (default 20).",
		"example": "--analyze=maze --board=catacombs --runs=20",
	},
	{
		"flag": "--out",
		"for": ["--analyze"],
		"value": Value.TEXT,
		"placeholder": "DIR",
		"help": "The folder the analysis report goes to (made when missing).",
		"example": "--analyze=pachinko --board=classic --out=reports",
	},
	{
		"flag": "--threads",
		"for": ["--analyze"],
		"value": Value.WHOLE,
		"placeholder": "T",
		"help": "Worker threads for the analysis (default: every core). Figures do not change.",
		"example": "--analyze=pachinko --threads=1",
	},
]


## The row for `flag` (such as "--seed"), or an empty Dictionary when there is none.
static func find(flag: String) -> Dictionary:
	for row: Dictionary in FLAGS:
		if row["flag"] == flag:
			return row
	return {}


## The key a flag's value has in the parsed values: "--check-boards" → "check_boards".
static func key_of(flag: String) -> String:
	return flag.trim_prefix("--").replace("-", "_")


## How a flag is written with its value, as help shows it: "--seed=N", "--hard".
static func usage_of(row: Dictionary) -> String:
	if row["value"] == Value.NONE:
		return str(row["flag"])
	return "%s=%s" % [row["flag"], row.get("placeholder", "VALUE")]
