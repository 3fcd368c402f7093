extends Node2D
## The board in layers, bottom to top as in the chapter: back plate, fascia art, ring
## border, launch path, gutter, pins, balls, pocket art, effects. `bind()` hands each layer
## the board; `fit()` scales the whole board into a rectangle of the screen.

const FASCIA_SIZE := 1000.0

@onready var backplate: Node2D = $Backplate
@onready var fascia: Sprite2D = $Fascia
@onready var ring_border: Node2D = $RingBorder
@onready var launch_path: Node2D = $LaunchPath
@onready var gutter: Node2D = $Gutter
@onready var pins: Node2D = $Pins
@onready var balls: Node2D = $Balls
@onready var pockets: Node2D = $Pockets
@onready var effects: Node2D = $Effects


## Shows the board and balls of `rules`.
func bind(rules: PachinkoRules) -> void:
	var level := rules.level
	backplate.call("setup", level)
	ring_border.call("setup", level)
	launch_path.call("setup", level)
	gutter.call("setup", level)
	pins.call("setup", level)
	pockets.call("setup", level)
	balls.call("bind", rules)
	fascia.position = level.ring_center
	fascia.scale = Vector2.ONE * (level.ring_radius * 2.0 / FASCIA_SIZE)


## Scales and places the board so its plate fills `area` (screen pixels), centred.
func fit(level: BoardLevel, area: Rect2) -> void:
	var half := level.ring_radius * 1.1 + 12.0
	var board_scale := minf(area.size.x, area.size.y) / (half * 2.0)
	scale = Vector2.ONE * board_scale
	position = area.get_center() - level.ring_center * board_scale


## Board coordinates of a screen point.
func to_board(screen: Vector2) -> Vector2:
	return (screen - position) / scale.x
