extends RefCounted
## Two pieces of the contact response that need more than one line: sliding along a
## curved surface, and finding the moment of impact. Internal to scripts/physics.

## Distances below this count as zero (px).
const EPS := 1e-6


## Velocity after a sliding contact (a persisting or gentle one): the normal speed is
## removed, except the part that only comes from the surface curving under a moving ball
## (capped by the curvature `curv` = substep time / radius of curvature). That part turns
## into tangential speed, so riding the ring or rolling round a cap loses nothing, while a
## push from gravity or other balls is never turned into speed.
static func slide(v: Vector2, nrm: Vector2, vn: float, gn_dt: float, curv: float) -> Vector2:
	var vt: Vector2 = v - nrm * vn
	if curv <= 0.0:
		return vt
	var t2: float = vt.length_squared()
	if t2 <= EPS:
		return vt
	var c: float = maxf(minf(vn - minf(gn_dt, 0.0), 0.0), -1.5 * t2 * curv)
	return vt * sqrt((t2 + c * c) / t2)


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
