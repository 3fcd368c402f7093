class_name AttackerBeacon
extends Node2D
## Makes the fever round's target plain: over every open attacker three chevrons flow down
## into its mouth ("aim here"), and a ring around it runs down with the round's seconds, so
## a player sees at a glance where to shoot and for how long. Reads BonusMachine; draws
## nothing (and sleeps) while no attacker is open.

## Chevrons over the mouth, and how many times a second they flow down a step.
const CHEVRONS := 3
const FLOW_HZ := 1.6
## Board pixels between chevrons, and between the lowest one and the attacker's own
## countdown line over its mouth (bonus_art.gd writes it half a width up).
const GAP := 13.0
const LIFT := 18.0
const HOT := Color("ffd84a")
const WARM := Color("ff8a2a")

var _level: BoardLevel
var _machine: BonusMachine
var _clock := 0.0


## Points at the attackers of `level` while `machine` has them open.
func bind(level: BoardLevel, machine: BonusMachine) -> void:
	_level = level
	_machine = machine
	if not machine.attacker_changed.is_connected(_on_attacker_changed):
		machine.attacker_changed.connect(_on_attacker_changed)
	set_process(machine.any_attacker_open())
	queue_redraw()


## True while some attacker is open and marked.
func is_pointing() -> bool:
	return _machine != null and _machine.any_attacker_open()


func _on_attacker_changed(_index: int, _open: bool) -> void:
	set_process(true)


func _process(delta: float) -> void:
	_clock += delta
	queue_redraw()
	if not is_pointing():
		set_process(false)


func _draw() -> void:
	if not is_pointing():
		return
	for i in _level.bonus_pockets.size():
		var spec := _level.bonus_pockets[i]
		if spec.role == BonusPocketSpec.Role.ATTACKER and _machine.is_open(i):
			_draw_chevrons(spec)
			_draw_time_ring(spec, i)


func _draw_chevrons(spec: BonusPocketSpec) -> void:
	var flow := fmod(_clock * FLOW_HZ, 1.0)
	var half := spec.width * 0.3
	for k in CHEVRONS:
		# k = 0 nearest the mouth; each slides one gap down per cycle and fades in at the top.
		var step := float(k) - flow
		var tip := spec.position + Vector2(0.0, -spec.width * 0.45 - LIFT - GAP * step)
		var fade := clampf(1.0 - step / CHEVRONS, 0.0, 1.0) * clampf(1.0 + step, 0.0, 1.0)
		var colour := Color(HOT.lerp(WARM, step / CHEVRONS), fade)
		var arm := Vector2(half, -half * 0.6)
		var points := PackedVector2Array([tip + Vector2(-arm.x, arm.y), tip, tip + arm])
		draw_polyline(points, Color(0.1, 0.02, 0.0, fade * 0.8), 6.0, true)
		draw_polyline(points, colour, 3.5, true)


func _draw_time_ring(spec: BonusPocketSpec, index: int) -> void:
	var share := clampf(_machine.time_left(index) / maxf(spec.open_seconds, 0.01), 0.0, 1.0)
	var centre := spec.position + Vector2(0.0, spec.depth * 0.5)
	var radius := spec.width * 0.5 + spec.depth * 0.5 + 6.0
	var pulse := 0.6 + 0.4 * sin(_clock * 10.0)
	draw_arc(centre, radius, 0.0, TAU, 64, Color(0.05, 0.0, 0.0, 0.5), 5.0, true)
	var start := -PI * 0.5
	draw_arc(centre, radius, start, start + TAU * share, 64, Color(HOT, pulse), 3.0, true)
