class_name JackpotSettle
extends RefCounted
## When a jackpot is really over for the player: its last round has ended and every ball
## that was in the air then has landed, so its payouts are in the tray. Trial 6: the JACKPOT
## OVER card counted before the last round's balls landed (533 paid, the panel 550 a moment
## later), and the MACHINE CLEARED card came up mid-jackpot and froze it.

## The jackpot that ended paying `paid` balls has settled: its last balls have landed.
signal settled(paid: int)

# The rules' jackpot rounds (not the rules: they hold this through their signals).
var _rounds: JackpotRounds
# Ids of the balls in the air now (launched, not yet landed, drained or rolled back).
var _flying := {}
# Ids still to land before the ended jackpot settles; -1 in _paid when none is waiting.
var _waiting := {}
var _paid := -1


## Follows `rules`' balls and jackpots from now on (bind before its first shot).
func _init(rules: PachinkoRules) -> void:
	_rounds = rules.bonus.rounds
	# methods, not lambdas: a lambda would keep this alive from the rules' side
	rules.ball_launched.connect(_on_launched)
	rules.ball_won.connect(_on_won)
	rules.ball_drained.connect(_land)
	rules.ball_returned.connect(_land)
	rules.bonus.jackpot_ended.connect(_on_jackpot_ended)


## True while a jackpot is on: its rounds, or its last round's balls still falling.
func busy() -> bool:
	return _rounds.active() or _paid >= 0


func _on_launched(id: int, _power: float, _speed: float) -> void:
	_flying[id] = true


func _on_won(id: int, _pocket: int, _payout: int, _at: Vector2) -> void:
	_land(id)


func _on_jackpot_ended(paid: int) -> void:
	_waiting = _flying.duplicate()
	_paid = paid
	_settle_when_landed()


func _land(id: int) -> void:
	_flying.erase(id)
	_waiting.erase(id)
	_settle_when_landed()


func _settle_when_landed() -> void:
	if _paid < 0 or not _waiting.is_empty():
		return
	var paid := _paid
	_paid = -1
	settled.emit(paid)
