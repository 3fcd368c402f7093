@tool
extends RefCounted
## How far a play analysis is, as one share of the whole run, and the time it has left.
## A pachinko run first climbs the rail at every power, then fires its shots: the bar covers
## both, so it moves from the first climbs on (before, it sat at 0 % through the climbs,
## 22 s of a 49 s run on Classic). The time left is the time so far scaled by the share
## still to do, once the run is far enough in for that to mean something.

## The climbs' share of a pachinko run's time: 22 s of 49 s on Classic, 10000 shots, 2 cores
## (tools: build a PachinkoAnalysis and poll climb_progress() and progress()).
const CLIMB_SHARE := 0.45
## No estimate before this share of the run or this many seconds: too early to tell.
const MIN_SHARE := 0.01
const MIN_SECONDS := 1.0


## The share (0..1) of a pachinko run done: `climbs` and `shots` are the shares of each
## phase (PachinkoAnalysis.climb_progress() and progress()).
static func pachinko_share(climbs: float, shots: float) -> float:
	return clampf(CLIMB_SHARE * climbs + (1.0 - CLIMB_SHARE) * shots, 0.0, 1.0)


## The seconds left when `share` of the run took `seconds`; -1 while it is too early to tell.
static func seconds_left(share: float, seconds: float) -> float:
	if share < MIN_SHARE or seconds < MIN_SECONDS:
		return -1.0
	return seconds * (1.0 - share) / share


## "about 40 s left", "about 3 min left", or "estimating the time left" (seconds_left -1).
static func left_words(left: float) -> String:
	if left < 0.0:
		return "estimating the time left"
	if left < 90.0:
		return "about %d s left" % maxi(roundi(left / 5.0) * 5, 5)
	return "about %d min left" % roundi(left / 60.0)


## The status line while a run goes on: what it is doing, how far, and the time left.
static func line(doing: String, share: float, seconds: float) -> String:
	# Tenths below 10 %: the first climbs move it at once (0.5 %), not only at 1 %.
	var percent := share * 100.0
	var done := (
		String.num(floorf(percent * 10.0) / 10.0, 1) if percent < 10.0 else str(floori(percent))
	)
	return "%s: %s %% done, %s." % [doing, done, left_words(seconds_left(share, seconds))]
