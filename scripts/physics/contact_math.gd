class_name ContactMath
extends RefCounted
## A piece of the contact response that needs more than one line: finding the moment of
## impact (the slide along a surface is written out in BallMover.respond(), which runs on
## every persisting contact). Internal to scripts/physics.

## Distances below this count as zero (px).
const EPS := 1e-6


## How long ago (0..h seconds) a ball at offset `d` from a round surface's centre, moving at
## `v`, was exactly `lim` away: used to bounce with the normal at the moment of impact, not
## the normal of the overlapped position. `inside` is true for the ring (ball within it).
static func back_off(d: Vector2, v: Vector2, lim: float, h: float, inside: bool) -> float:
	var vv: float = v.length_squared()
	if vv <= EPS:
		return 0.0
	var dv: float = d.dot(v)
	var disc: float = dv * dv - vv * (d.length_squared() - lim * lim)
	if disc < 0.0:
		return 0.0
	var root: float = sqrt(disc)
	var s: float = (dv - root) / vv if inside else (dv + root) / vv
	return clampf(s, 0.0, h)
