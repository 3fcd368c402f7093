extends SceneTree
## Builds the two bonus-layer boards with the board editor's own actions (pin rows, pocket
## stamps, the bonus tool's AddBonus in mirror mode), checks each with BoardValidator and
## saves it with its level scene:
##   tools/godot.sh --headless --path . -s res://tools/make_bonus_boards.gd
## pachinko/fever: rows of pins over a start pocket with a funnel, the attacker low on the
## far side, two tulips and a plain pocket.
## pachinko/hanami: a denser field with two start pockets, a high attacker on the far side
## and four tulips.

const MakeOriginalBoards := preload("res://tools/make_original_boards.gd")
const ActionHistory := preload("res://addons/board_editor/core/action_history.gd")
const PatternAction := preload("res://addons/board_editor/actions/pattern_action.gd")
const PocketAction := preload("res://addons/board_editor/actions/pocket_action.gd")
const AddItemsAction := preload("res://addons/board_editor/actions/add_items_action.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const Mirror := preload("res://addons/board_editor/core/mirror.gd")
const BonusActions := preload("res://addons/board_editor/bonus/bonus_actions.gd")

const CENTER := 350.0
const ROLE := BonusPocketSpec.Role
## Symbols per reel: a jackpot (three alike) comes once in SYMBOLS² spins. Rare and big
## (issue 41): with JackpotRounds' ten rounds a jackpot pays over 100 balls. 9 (1 in 81; 7
## before): both boards' start pockets sit under the middle strengths, so with 7 a handle
## held there drew jackpots so often it paid two balls a ball. With rarer jackpots, start
## pockets paying 1 and the payouts below, no held strength pays much more than another
## (tools/power_returns.gd) and the return at uniform power stays in 0.80 to 0.95.
const SYMBOLS := 9
## Balls in the cup at the start: enough for a session of minutes at a steady pace
## (`--sessions=20`: median over 4 minutes, 10th percentile over 90 s).
const FEVER_CUP := 100
const HANAMI_CUP := 100
## The attackers, one each, off the middle on the far (left) side: a jackpot asks for a
## stronger handle than play between jackpots (the default 60 feeds the start pockets),
## as a real machine's "shoot right" does. tools/attacker_band.gd: catches a round by power
## peak at 75 to 85 on both (with the attacker in the middle they peaked near 60 to 75,
## where the handle already sat, so a jackpot asked nothing of the player).
const FEVER_ATTACKER := Vector2(240, 500)
const HANAMI_ATTACKER := Vector2(280, 330)
## What a catch pays: off the middle an attacker catches fewer balls at uniform power (the
## analysis' jackpot: 113 -> 74 on Fever, 71 on Hanami at the old 11 and 13), so a catch
## pays more, for a jackpot of 100 balls or more at uniform power.
const FEVER_CATCH := 17
const HANAMI_CATCH := 20
## Fever's one plain pocket (the left one of the pair gave its place to the attacker): it
## pays 7, not 6, for the return the lost pocket took with it.
const FEVER_POCKET_PAYOUT := 7


func _initialize() -> void:
	var ok := true
	for board: BoardLevel in [make_fever(), make_hanami()]:
		ok = _save(board) and ok
	quit(0 if ok else 1)


## Fever: the start pocket sits in the middle under a funnel of pins; a jackpot opens the
## wide attacker low on the far side (FEVER_ATTACKER); tulips on the flanks and a plain
## pocket on the near side.
static func make_fever() -> BoardLevel:
	var history := ActionHistory.new()
	var level := MakeOriginalBoards.pachinko_base(
		history,
		"fever",
		"Fever",
		"Hit the start pocket to spin the reels: three of a kind opens the attacker below."
	)
	level.fascia = "neon"
	level.cup_start_balls = FEVER_CUP
	_rows(history, level, 13, 34.0, 36.0, 130.0)
	MakeOriginalBoards.erase_pins_outside_field(history, level, 22.0)
	MakeOriginalBoards.shape_launch(history, level, LaunchRail.AIMING_END_DEG)
	_clear_reels(history, level)
	var windmill := {"kind": "circle", "count": 6, "spacing": 16.0}
	var spot := Vector2(350, 215)
	MakeOriginalBoards.erase_pins_in(
		history, level, Rect2(spot - Vector2(30, 30), Vector2(60, 60)), CENTER
	)
	history.commit(PatternAction.new(level, windmill, spot, CENTER))
	_bonus(history, level, ROLE.START, Vector2(350, 400), 26.0, 1, {"symbols": SYMBOLS})
	_funnel(history, level, Vector2(350, 400), 13.0)
	var attacker := {"open_seconds": 10.0, "open_catches": 10}
	_bonus(history, level, ROLE.ATTACKER, FEVER_ATTACKER, 64.0, FEVER_CATCH, attacker, false)
	# The funnel reaches past the cleared cup: clear round it too so no pin pinches a ball.
	var funnel_room := Rect2(FEVER_ATTACKER + Vector2(-32 - 44, -50), Vector2(2 * (32 + 44), 40))
	MakeOriginalBoards.erase_pins_in(history, level, funnel_room, FEVER_ATTACKER.x)
	_funnel(history, level, FEVER_ATTACKER, 32.0, false)
	_guard(history, level, FEVER_ATTACKER + Vector2(0.0, 38.0 + 11.0))
	_bonus(history, level, ROLE.TULIP, Vector2(150, 330), 26.0, 3, {})
	# one plain pocket, on the side the handle's middle strengths feed
	var pocket := Vector2(460, 480)
	MakeOriginalBoards.erase_pins_in(history, level, _clear_rect(pocket, 24.0, 26.0), pocket.x)
	history.commit(PocketAction.new(level, pocket, 24.0, 26.0, FEVER_POCKET_PAYOUT))
	return level


## Hanami: a dense field of pins; two start pockets low on either side, the attacker high on
## the far side (HANAMI_ATTACKER), and four tulips.
static func make_hanami() -> BoardLevel:
	var history := ActionHistory.new()
	var level := MakeOriginalBoards.pachinko_base(
		history,
		"hanami",
		"Hanami",
		"Four tulips and two start pockets: a jackpot lifts the attacker's lid on the left."
	)
	level.fascia = "sakura"
	level.cup_start_balls = HANAMI_CUP
	_rows(history, level, 17, 28.0, 30.0, 120.0)
	MakeOriginalBoards.erase_pins_outside_field(history, level, 22.0)
	MakeOriginalBoards.shape_launch(history, level, LaunchRail.AIMING_END_DEG)
	_clear_reels(history, level)
	_bonus(history, level, ROLE.START, Vector2(265, 450), 26.0, 1, {"symbols": SYMBOLS})
	var attacker := {"open_seconds": 15.0, "open_catches": 10}
	_bonus(history, level, ROLE.ATTACKER, HANAMI_ATTACKER, 60.0, HANAMI_CATCH, attacker, false)
	_bonus(history, level, ROLE.TULIP, Vector2(210, 260), 26.0, 5, {})
	_bonus(history, level, ROLE.TULIP, Vector2(240, 570), 26.0, 2, {})
	return level


# `count` rows of pins, `spacing` apart, every other row shifted half a step.
static func _rows(
	history: ActionHistory, level: BoardLevel, count: int, spacing: float, gap: float, top: float
) -> void:
	var per_row := int(600.0 / spacing)
	for row in count:
		var pattern := {"kind": "row", "count": per_row - row % 2, "spacing": spacing}
		var x := CENTER + (spacing * 0.5 if row % 2 == 1 else 0.0)
		history.commit(PatternAction.new(level, pattern, Vector2(x, top + row * gap)))


# A pin just under a cup's catching pin at `below`: balls bouncing up under the cup hit it
# instead of touching the catching pin from outside (which pays as if caught).
static func _guard(history: ActionHistory, level: BoardLevel, below: Vector2) -> void:
	var guard := BoardItems.empty_set()
	guard["pins"] = PackedVector2Array([below])
	history.commit(AddItemsAction.new(level, guard, "Add pin"))


# Clears the pins round a cup and adds a bonus pocket there (and its mirror image).
static func _bonus(
	history: ActionHistory,
	level: BoardLevel,
	role: BonusPocketSpec.Role,
	mouth: Vector2,
	width: float,
	payout: int,
	extra: Dictionary,
	mirrored := true
) -> void:
	var axis := CENTER if mirrored else mouth.x  # a pocket on its own axis is not doubled
	var depth := maxf(width * 0.5 + 6.0, 26.0)
	MakeOriginalBoards.erase_pins_in(history, level, _clear_rect(mouth, width, depth), axis)
	var spec := BonusPocketSpec.of_role(role, mouth, width, depth, payout)
	for key: String in extra:
		spec.set(key, extra[key])
	history.commit(BonusActions.AddBonus.new(level, spec, axis))


# Room round a cup: a ball's width beside the rim and the wings' reach above the mouth.
static func _clear_rect(mouth: Vector2, width: float, depth: float) -> Rect2:
	var half := width * 0.5 + 22.0
	return Rect2(mouth - Vector2(half, 34.0), Vector2(half * 2.0, depth + 44.0))


# Two short slanted rows of pins above `mouth` that steer balls into it (and its mirror image
# when `mirrored` and off the middle).
static func _funnel(
	history: ActionHistory, level: BoardLevel, mouth: Vector2, half: float, mirrored := true
) -> void:
	var pins := PackedVector2Array()
	for side: float in [-1.0, 1.0]:
		for step in 3:
			pins.append(mouth + Vector2(side * (half + 10.0 + step * 10.0), -16.0 - step * 10.0))
	var funnel := BoardItems.empty_set()
	funnel["pins"] = pins
	var data := funnel if mouth.x == CENTER or not mirrored else Mirror.mirror_set(funnel, CENTER)
	history.commit(AddItemsAction.new(level, data, "Add pin"))


# Validates and writes the board and its level scene; false (and why) on a failure.
static func _save(level: BoardLevel) -> bool:
	var errors := BoardValidator.errors(level)
	for issue in BoardValidator.validate(level):
		print("  %s" % issue)
	if not errors.is_empty():
		push_error("make_bonus_boards: %s has %d errors." % [level.board_id, errors.size()])
		return false
	var id := level.board_id.trim_prefix("pachinko_")
	var path := "res://levels/pachinko/%s.board" % id
	var error := ResourceSaver.save(level, path)
	var scene_path := "res://scenes/boards/pachinko_%s.tscn" % id
	var scene := FileAccess.open(scene_path, FileAccess.WRITE)
	if error != OK or scene == null:
		push_error("make_bonus_boards: could not write %s or its scene" % path)
		return false
	scene.store_string(MakeOriginalBoards.SCENE_TEXT % path)
	scene.close()
	var bonus := level.bonus_pockets.size()
	print("wrote %s (%d pins, %d bonus pockets)" % [path, level.pins.size(), bonus])
	return true


# No pins under the reels or within 16 px of their frame: no pin hides behind them and no
# ball wedges between the frame and a pin.
static func _clear_reels(history: ActionHistory, level: BoardLevel) -> void:
	var half := BonusGeometry.REEL_HALF + Vector2(22.0, 22.0 + BonusGeometry.REEL_ROOF)
	MakeOriginalBoards.erase_pins_in(
		history, level, Rect2(BonusGeometry.reel_spot(level) - half, half * 2.0), CENTER
	)
