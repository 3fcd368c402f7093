class_name LaunchTable
extends RefCounted
## A board's launch rail as measured: launch speeds at the bottom of the rail and the speed
## each ball had when it passed the rail's mouth, slowest first. Energy makes the square of
## the mouth speed nearly linear in the square of the launch speed (friction and the hop
## between the rail's walls bend it a little), so the table is read by straight lines
## between its samples in squared speeds. Made by LaunchCalibration; read-only afterwards,
## so any thread may read it.

## Launch speeds at the bottom of the rail (px/s), rising.
var bottom := PackedFloat64Array()
## The speed at the mouth each launch speed gave (px/s), never falling.
var mouth := PackedFloat64Array()


## Adds a measured sample; samples must come slowest launch first. A mouth speed lower than
## the one before (a bump in the measurement) is held at the one before, so the table
## never turns back.
func add(bottom_speed: float, at_mouth: float) -> void:
	if not mouth.is_empty():
		at_mouth = maxf(at_mouth, mouth[mouth.size() - 1])
	bottom.append(bottom_speed)
	mouth.append(at_mouth)


## The launch speed at the bottom that gives `wanted` px/s at the mouth. Slower than the
## slowest sample: the slowest launch (it still clears the rail). Faster than the fastest:
## the fastest launch.
func launch_speed_for(wanted: float) -> float:
	if bottom.is_empty():
		return 0.0
	if wanted <= mouth[0]:
		return bottom[0]
	var target := wanted * wanted
	for k in range(1, mouth.size()):
		if mouth[k] < wanted:
			continue
		var m0 := mouth[k - 1] * mouth[k - 1]
		var m1 := mouth[k] * mouth[k]
		var b0 := bottom[k - 1] * bottom[k - 1]
		var b1 := bottom[k] * bottom[k]
		var t := (target - m0) / (m1 - m0) if m1 > m0 else 1.0
		return sqrt(lerpf(b0, b1, t))
	return bottom[bottom.size() - 1]


## The launch speed at the bottom of the rail for flipper `power` (0..100): its mouth speed
## runs from the slowest one the rail lets through (power 0) up to EXIT_SPEED_MAX (power
## 100) along LaunchPower.mouth_share, so every power clears the rail and aims.
func launch_speed(power: float) -> float:
	return launch_speed_for(mouth_speed(power))


## The speed at the rail's mouth that flipper `power` (0..100) aims for.
func mouth_speed(power: float) -> float:
	var slowest := slowest_mouth_speed()
	var fastest := maxf(LaunchPower.EXIT_SPEED_MAX, slowest)
	return lerpf(slowest, fastest, LaunchPower.mouth_share(power))


## The slowest mouth speed the table holds (the weakest shot's).
func slowest_mouth_speed() -> float:
	return mouth[0] if not mouth.is_empty() else 0.0
