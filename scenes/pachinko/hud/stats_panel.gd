class_name StatsPanel
extends PanelContainer
## Session numbers: shots, where the balls went, hits per pocket, the balls paid back this
## session (one game, a full cup to an empty one), the best session on this board and the
## machine's goal against the tray now.

## The font size of the numbers.
const FONT_SIZE := 15

## Most balls won in one game on this board before (CupPeak), or -1 for none yet.
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


# The tray now against its start ("start_balls" in the stats, the game's screen adds it)
# beside the best game's most won ("won": this game's peak raises it as it passes it);
# without them, the best alone. Trial 6 read "Won" (this game's peak) as the tray's gain.
static func _won_line(stats: Dictionary, best: int) -> String:
	var won: int = stats.get("won", -1)
	if won >= 0 and stats.has("start_balls"):
		var start: int = stats["start_balls"]
		var change: int = stats.get("balls_left", 0) - start
		var now := "[b]Up[/b] %d" % change if change >= 0 else "[b]Down[/b] %d" % -change
		return "%s this game · [b]best game[/b] %d" % [now, maxi(best, won)]
	if won >= 0:
		return "[b]Won[/b] %d · [b]best game[/b] %d" % [won, maxi(best, won)]
	return "[b]Most won[/b] %d balls" % best if best >= 0 else "[b]Most won[/b] none yet"


## The panel's lines for `stats`, in the words the card and the game-over box use:
## "pocket hits" counts every paying piece (pockets, start pockets, attackers, tulips),
## "paid back" the balls they paid into the cup; `best` is the most balls a game on the
## board has won (its tray's most above its start, CupPeak; -1: none); `target` the machine's
## tray target (0: none), shown against the balls in the tray now ("balls_left"), or as
## cleared once `cleared`, or as clearing once the jackpot ends while `pending`.
static func lines_for(
	stats: Dictionary, best := -1, target := 0, cleared := false, pending := false
) -> PackedStringArray:
	var hits := 0
	for count: int in stats.get("pocket_hits", []):
		hits += count
	var shots: int = stats.get("shots", 0)
	var paid: int = stats.get("payouts", 0)
	var ratio: float = stats.get("payout_ratio", 0.0)
	var lines := PackedStringArray(
		[
			"[b]Shots[/b] %d    [b]In play[/b] %d" % [shots, stats.get("in_play", 0)],
			"[b]Pocket hits[/b] %d    [b]Gutter[/b] %d" % [hits, stats.get("drained", 0)],
			# short lines: longer ones wrapped and pushed the launcher off a 720 px column
			"[b]Paid back[/b] %d (%.2f a shot)" % [paid, ratio],
			_won_line(stats, best),
		]
	)
	if target > 0:
		# always one line from the start, so the panel never grows when it changes
		var now: int = stats.get("balls_left", 0)
		var goal_line := "[b]Goal[/b] %d · %d now" % [target, now]
		if cleared:
			goal_line = "[b]Goal[/b] %d · cleared!" % target
		elif pending:
			# trial 7: the tray passed the goal in a jackpot and nothing said so for minutes
			goal_line = "[b]Goal[/b] %d · clears after jackpot" % target
		lines.append(goal_line)
	return lines
