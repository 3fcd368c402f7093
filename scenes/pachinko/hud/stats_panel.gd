class_name StatsPanel
extends PanelContainer
## One game's numbers in three lines, each the answer to a player's question: how many balls
## do I have and how far is the goal ("Balls 107 · goal 127"), how am I doing against my best
## ("Won this game +7 · best +11"), and is anything going in ("Pocket hits 5 of 40 shots").
## The balls are the tray's own count (CupDisplay): a ball in flight is not in it. Trials 7
## and 8 read the old six lines twice and found four different ball counts in them.

## The font size of the numbers.
const FONT_SIZE := 15

## The best result of a finished game on this board (balls ended with less balls started,
## PachinkoGameRecord), or -1 for none yet.
var best_session := -1
## The machine's goal, the tray's target (PachinkoGoals; 0: none, no goal line).
var goal := 0
## True once this game reached the goal.
var goal_cleared := false
## True while the tray has passed the goal during a jackpot: the clear waits for its end.
var goal_pending := false

var _text: RichTextLabel


func _ready() -> void:
	_text = RichTextLabel.new()
	_text.bbcode_enabled = true
	_text.fit_content = true
	_text.scroll_active = false
	_text.autowrap_mode = TextServer.AUTOWRAP_WORD
	_text.custom_minimum_size = Vector2(10, 0)
	_text.add_theme_font_size_override("normal_font_size", FONT_SIZE)
	_text.add_theme_font_size_override("bold_font_size", FONT_SIZE)
	add_child(_text)


## Shows `stats` (PachinkoRules.stats(true): this game's figures).
func show_stats(stats: Dictionary) -> void:
	if _text == null:
		return
	_text.text = "\n".join(lines_for(stats, best_session, goal, goal_cleared, goal_pending))


## The text the panel shows now, without its markup.
func shown_text() -> String:
	return _text.get_parsed_text() if _text != null else ""


# This game's result so far, the tray against its start ("start_balls", the game's screen
# adds it), beside the best result kept; without a start, the best alone.
static func _won_line(stats: Dictionary, best: int) -> String:
	var best_words := "[b]best[/b] +%d" % best if best >= 0 else "[b]best[/b] none yet"
	if stats.has("start_balls"):
		var start: int = stats["start_balls"]
		var change: int = stats.get("balls_left", 0) - start
		if change >= 0:
			return "[b]Won this game[/b] +%d · %s" % [change, best_words]
		return "[b]Down[/b] %d this game · %s" % [-change, best_words]
	return "[b]Best game[/b] +%d" % best if best >= 0 else "[b]Best game[/b] none yet"


# The balls held ("balls_left": the tray's count) against the machine's `target` (0: none).
static func _balls_line(stats: Dictionary, target: int, cleared: bool, pending: bool) -> String:
	var balls := "[b]Balls[/b] %d" % stats.get("balls_left", 0)
	if target <= 0:
		return balls
	if cleared:
		return "%s · [b]goal[/b] %d cleared!" % [balls, target]
	if pending:
		# trial 7: the tray passed the goal in a jackpot and nothing said so for minutes
		return "%s · [b]goal[/b] %d reached" % [balls, target]
	return "%s · [b]goal[/b] %d" % [balls, target]


## The panel's lines for `stats`, in the words the card and the game-over box use: "pocket
## hits" counts every paying piece (pockets, start pockets, attackers, tulips); "balls_left"
## is the tray's count, "start_balls" what the game began with; `best` the board's best
## result (-1: none); `target` the machine's goal (0: none), shown cleared once `cleared`,
## or reached (the clear waits for the jackpot's end) while `pending`.
static func lines_for(
	stats: Dictionary, best := -1, target := 0, cleared := false, pending := false
) -> PackedStringArray:
	var hits := 0
	for count: int in stats.get("pocket_hits", []):
		hits += count
	# short lines: longer ones wrapped and pushed the launcher off a 720 px column
	return PackedStringArray(
		[
			_balls_line(stats, target, cleared, pending),
			_won_line(stats, best),
			"[b]Pocket hits[/b] %d of %d shots" % [hits, stats.get("shots", 0)],
		]
	)
