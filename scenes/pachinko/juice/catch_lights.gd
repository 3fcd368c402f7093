class_name CatchLights
extends Node
## A pocket that catches a ball lights its rim pins in the colour of what it is: gold for
## a plain pocket, sky blue for a start pocket, orange for an attacker, pink for a tulip
## (PinLights fades them). Reads the rules' `ball_won`; changes nothing in the game.

const POCKET := Color(1.0, 0.78, 0.3)
const ROLE_TINTS: Array[Color] = [Color("5ab4ff"), Color("ff7a2a"), Color("ff7ad0")]

var _level: BoardLevel
var _lights: PinLights


## Lights `lights`' pins when a pocket of `rules`' board catches a ball.
func bind(rules: PachinkoRules, lights: PinLights) -> void:
	_level = rules.level
	_lights = lights
	rules.ball_won.connect(_on_ball_won)


## The colour world pocket `pocket_id` of `level` lights in.
static func tint_of(level: BoardLevel, pocket_id: int) -> Color:
	var index := BonusGeometry.bonus_index(level, pocket_id)
	if index < 0 or index >= level.bonus_pockets.size():
		return POCKET
	return ROLE_TINTS[level.bonus_pockets[index].role]


func _on_ball_won(_id: int, pocket: int, _payout: int, _at: Vector2) -> void:
	if _lights != null:
		_lights.light_pocket(pocket, tint_of(_level, pocket))
