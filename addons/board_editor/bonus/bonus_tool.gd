@tool
extends "res://addons/board_editor/tools/board_tool.gd"
## Places one kind of bonus pocket (start pocket, attacker or tulip): a click adds one with
## that role's standard size and payout at the snapped mouse position (and its mirror image
## in mirror mode); a click on an existing bonus pocket removes it. Each click is one
## undoable action. Finer values (payout, symbols, open seconds) are edited in the dock's
## Selection panel after picking the pocket with the Select tool.

const BonusActions := preload("res://addons/board_editor/bonus/bonus_actions.gd")
## Per role: [width, payout]; the depth follows from the width (a round-bottomed cup).
const DEFAULTS := {
	BonusPocketSpec.Role.START: [26.0, 3],
	BonusPocketSpec.Role.ATTACKER: [64.0, 12],
	BonusPocketSpec.Role.TULIP: [26.0, 4],
}

## The role this tool places.
var role: BonusPocketSpec.Role


func _init(on_session: BoardEditSession, placed_role: BonusPocketSpec.Role) -> void:
	super(on_session)
	role = placed_role


func press(at: Vector2, _event: InputEventMouseButton) -> bool:
	var under := pocket_at(level(), at)
	if under >= 0:
		# A hidden or locked "Bonus pieces" layer keeps its pockets: the click does nothing.
		if session.can_pick(BoardItems.make(BoardItems.Kind.BONUS, under)):
			session.commit(BonusActions.RemoveBonus.new(level(), under))
		return true
	session.commit(
		BonusActions.AddBonus.new(level(), spec_at(session.snap_point(at)), session.mirror_axis())
	)
	return true


## A new pocket of this tool's role with its mouth at `mouth`.
func spec_at(mouth: Vector2) -> BonusPocketSpec:
	var values: Array = DEFAULTS[role]
	var width: float = values[0]
	var payout: int = values[1]
	var spec := BonusPocketSpec.of_role(role, mouth, width, maxf(width * 0.5 + 6.0, 26.0), payout)
	if role == BonusPocketSpec.Role.START:
		spec.symbols = 3
	return spec


## The index of the bonus pocket whose cup holds `at`, or -1.
static func pocket_at(board: BoardLevel, at: Vector2) -> int:
	for i in range(board.bonus_pockets.size() - 1, -1, -1):
		var spec := board.bonus_pockets[i]
		if spec != null and BonusChecks.cup_rect(board, spec).grow(2.0).has_point(at):
			return i
	return -1


func draw(canvas: Control, to_screen: Transform2D) -> void:
	var board := level()
	if pocket_at(board, hover) >= 0:
		var spec := board.bonus_pockets[pocket_at(board, hover)]
		var box := BonusChecks.cup_rect(board, spec)
		OverlayDraw.line(canvas, to_screen, box.position, box.end, Color(1, 0.3, 0.3))
		OverlayDraw.line(
			canvas,
			to_screen,
			Vector2(box.position.x, box.end.y),
			Vector2(box.end.x, box.position.y),
			Color(1, 0.3, 0.3)
		)
		return
	var mouths := PackedVector2Array([session.snap_point(hover)])
	if session.mirror_enabled:
		mouths.append(Vector2(2.0 * session.mirror_axis() - mouths[0].x, mouths[0].y))
	for mouth in mouths:
		var spec := spec_at(mouth)
		OverlayDraw.ghost_points(
			canvas, to_screen, BonusGeometry.rim_pins(board, spec), board.pin_radius
		)
		var half := Vector2(spec.width * 0.5, 0)
		OverlayDraw.line(canvas, to_screen, mouth - half, mouth + half, OverlayDraw.GHOST_COLOR)
