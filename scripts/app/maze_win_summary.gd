class_name MazeWinSummary
extends RefCounted
## What a maze win says: the time, the medal earned (or how far it was from the next one),
## and the change against the best time before it. Plain data for the win panel and tests.

## The finishing time in seconds.
var seconds := 0.0
## The medal this run earned.
var medal := Medals.Medal.NONE
## The next better medal (NONE after gold or on a board without medal times).
var next_medal := Medals.Medal.NONE
## Seconds this run was slower than next_medal's time (0 when there is none).
var short_by := 0.0
## The best time before this run (-1 when there was none).
var previous_best := -1.0
## True when this run is the new best time.
var new_best := false
## The finishing time as the clock shows it (tenths).
var seconds_shown := 0.0


## The summary of a win in `seconds` on `level` in hard or easy mode, with the best time
## before it `previous_best` (-1 = never finished).
static func of(
	level: BoardLevel, hard: bool, won_seconds: float, best_before: float
) -> MazeWinSummary:
	var summary := MazeWinSummary.new()
	var times := Medals.times_for(level, hard)
	summary.seconds = won_seconds
	summary.previous_best = best_before
	summary.new_best = best_before <= 0.0 or won_seconds < best_before
	summary.medal = Medals.medal_for_time(times, won_seconds)
	if times.size() == 3 and summary.medal != Medals.Medal.GOLD:
		summary.next_medal = (summary.medal + 1) as Medals.Medal
		summary.seconds_shown = Medals.shown_time(won_seconds)
		summary.short_by = summary.seconds_shown - Medals.time_of(times, summary.next_medal)
	return summary


## The card's title: the medal once ("Silver!"), or "Finished!" without one.
func headline() -> String:
	return "%s!" % Medals.name_of(medal) if medal != Medals.Medal.NONE else "Finished!"


## The line under the title, which does not say the medal again (the title does): "1.8 s
## short of Gold" after silver or bronze, "Bronze is under 1:30.0" without a medal (kind,
## not a gap of minutes to the tenth), or "" after gold or on a board without medal times.
func medal_line() -> String:
	if next_medal == Medals.Medal.NONE:
		return ""
	if medal == Medals.Medal.NONE:
		return "%s is under %s" % [Medals.name_of(next_medal), clock(seconds_shown - short_by)]
	return "%s s short of %s" % [_tenths(short_by), Medals.name_of(next_medal)]


## The best-time line: "First finish: that is your best", "New best: 2.3 s faster", or
## "0.8 s slower than your best (0:41.2)".
func best_line() -> String:
	if previous_best <= 0.0:
		return "Your first finish: that's your best time"
	var delta := seconds - previous_best
	if delta < 0.0:
		return "New best: %s s faster than before" % _tenths(-delta)
	if is_zero_approx(delta):
		return "Exactly your best time"
	return "%s s slower than your best (%s)" % [_tenths(delta), clock(previous_best)]


## "m:ss.t" for a time in seconds, the way the game shows times.
static func clock(time: float) -> String:
	# the small nudge keeps 36.3 from showing as 36.2 (36.3 · 10 is 362.99999... in binary)
	var tenths := floori(maxf(time, 0.0) * 10.0 + 1e-6)
	return "%d:%02d.%d" % [floori(tenths / 600.0), floori(tenths / 10.0) % 60, tenths % 10]


# Seconds with one decimal, never shown as 0.0 for a real difference.
static func _tenths(value: float) -> String:
	return "%.1f" % maxf(ceilf(value * 10.0 - 1e-6) / 10.0, 0.1)
