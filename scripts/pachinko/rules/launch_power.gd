class_name LaunchPower
extends RefCounted
## Flipper power (0..100) to the speed a ball should have at the launch rail's mouth, where
## it leaves the rail for the field.
##
## The mouth speed is what aims: a ball that only just clears the rail tips over the mouth
## and drops into the pins beside the rail, a faster one flies up and left before it falls,
## and the fastest ride the ring across the top to the far side. Every power clears the
## rail: power 0 gives the slowest mouth speed the board's rail lets through, power 100
## EXIT_SPEED_MAX, and `mouth_share` spaces the powers between. What it takes at the bottom
## of the rail to reach a mouth speed depends on the board's rail and physics, so
## LaunchTable measures it on the board's own world.

## Mouth speed at full power (px/s, 20 px per 30 ms tick): it rides the ring over the top.
## The slowest is about 140-170 px/s (the chapter's weakest shot is 117), so full power is
## 3.5-4 times the weakest, as the chapter's 3.5 to 10 px per tick is 2.9 times.
const EXIT_SPEED_MAX := 700.0
## How the powers are spaced between the slowest and the fastest mouth speed: share =
## (power / 100) ^ SHARE_EXPONENT. A ball's landing moves slowly with speed at first (it
## drops near the rail) and fast at the top (it starts to ride the ring), so the low powers
## get the finer steps and the handle aims evenly across the field.
const SHARE_EXPONENT := 1.5
const MAX_POWER := 100.0


## Where `power` lies between the slowest (0) and the fastest (1) mouth speed.
static func mouth_share(power: float) -> float:
	return pow(clampf(power, 0.0, MAX_POWER) / MAX_POWER, SHARE_EXPONENT)


## Power (0..100) from a drag: the chapter measures how far the pointer moved up from where
## the press began, one pixel per point of power.
static func power_from_drag(origin: Vector2, point: Vector2) -> float:
	return clampf(origin.y - point.y, 0.0, MAX_POWER)


## Flipper rotation for a power: 0 to 20 degrees (the chapter's power / 5).
static func flipper_degrees(power: float) -> float:
	return clampf(power, 0.0, MAX_POWER) / 5.0
