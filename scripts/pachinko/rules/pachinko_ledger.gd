class_name PachinkoLedger
extends RefCounted
## Where every ball went. Balls come in from the start of a game (the cup fill) and from
## pocket payouts; each one is then in the cup, loaded, in play, drained or won (caught by
## a pocket). `balances()` checks that those add up, so no ball is ever lost silently.

const _COUNTERS: Array[String] = [
	"given", "paid", "gold", "shots", "drained", "won", "returned", "nudges", "vanished"
]

## Balls put in the cup when games started.
var given := 0
## Balls paid into the cup by pockets.
var paid := 0
## Balls the gold pins added to the cup (one a pin put out).
var gold := 0
## Balls launched.
var shots := 0
## Balls swallowed by the gutter.
var drained := 0
## Balls caught by a pocket (each paid out).
var won := 0
## Weak shots that rolled back down the rail into the cup.
var returned := 0
## Stuck balls given a nudge.
var nudges := 0
## Balls the world removed without telling the rules (should stay 0; counted as drained).
var vanished := 0
## Catches per pocket, by world pocket id: the board's pockets, then its bonus pockets
## (start pockets, attackers, tulips: every piece that pays).
var pocket_hits := PackedInt32Array()
## Balls paid per pocket, by pocket index.
var pocket_payouts := PackedInt32Array()


func _init(pocket_count: int) -> void:
	pocket_hits.resize(maxi(pocket_count, 0))
	pocket_payouts.resize(maxi(pocket_count, 0))


## Records a catch by `pocket` paying `payout` balls.
func record_win(pocket: int, payout: int) -> void:
	won += 1
	paid += payout
	if pocket >= 0 and pocket < pocket_hits.size():
		pocket_hits[pocket] += 1
		pocket_payouts[pocket] += payout


## A copy of the counts as they are now.
func copy() -> RefCounted:
	var script: GDScript = get_script()
	var other: RefCounted = script.new(pocket_hits.size())
	for key: String in _COUNTERS:
		other.set(key, get(key))
	other.set("pocket_hits", pocket_hits.duplicate())
	other.set("pocket_payouts", pocket_payouts.duplicate())
	return other


## The counts since `earlier` (a copy taken before, see copy()): this one's less its.
func since(earlier: RefCounted) -> RefCounted:
	var other := copy()
	for key: String in _COUNTERS:
		var now: int = get(key)
		var before: int = earlier.get(key)
		other.set(key, now - before)
	var hits := pocket_hits.duplicate()
	var pays := pocket_payouts.duplicate()
	var hits_before: PackedInt32Array = earlier.get("pocket_hits")
	var pays_before: PackedInt32Array = earlier.get("pocket_payouts")
	for i in mini(hits_before.size(), hits.size()):
		hits[i] -= hits_before[i]
		pays[i] -= pays_before[i]
	other.set("pocket_hits", hits)
	other.set("pocket_payouts", pays)
	return other


## True when cup + loaded + in play + drained + won equals every ball ever given or paid.
func balances(cup: int, loaded: int, in_play: int) -> bool:
	return cup + loaded + in_play + drained + won == given + paid + gold


## Shots that reached the field: launches minus weak shots that rolled back to the cup.
func field_shots() -> int:
	return maxi(shots - returned, 0)


## Balls paid back per ball that reached the field (0 before the first), the gold pins'
## balls included. A weak shot that rolled back cost nothing, so it is not a shot here.
func payout_ratio() -> float:
	var played := field_shots()
	return float(paid + gold) / float(played) if played > 0 else 0.0


## A plain snapshot for the stats panel, the autoplay JSON and tests.
func to_dict() -> Dictionary:
	var hits: Array[int] = []
	var pays: Array[int] = []
	for i in pocket_hits.size():
		hits.append(pocket_hits[i])
		pays.append(pocket_payouts[i])
	return {
		"given": given,
		"shots": shots,
		"pocket_hits": hits,
		"pocket_payouts": pays,
		"payouts": paid,
		"gold_balls": gold,
		"won": won,
		"drained": drained,
		"returned": returned,
		"nudges": nudges,
		"vanished": vanished,
		"payout_ratio": snappedf(payout_ratio(), 0.001),
	}
