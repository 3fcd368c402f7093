class_name BoardPainter
extends RefCounted
## Draws any board onto a CanvasItem from inside its `_draw()`: the editor's board node,
## level-select thumbnails and the games' static board layer all use it.
##
## Everything is drawn in board pixels through `xform` (board → canvas item). Special pins
## are diamonds as well as gold, so they read without colour. A pachinko board's background
## and ring are its machine's (FasciaBook): the plate colour, the art faded behind the pins.

## Layers to draw (combine with |).
enum Layer {
	BACKGROUND = 1,
	RING = 2,
	RAIL = 4,
	GUTTER = 8,
	PINS = 16,
	POCKETS = 32,
	WALLS = 64,
	HOLES = 128,
	GOAL = 256,
	STARTS = 512,
	BONUS = 1024,
	WINDMILLS = 2048,
	FLOOR_ARROWS = 4096,
	ALL = 8191,
}

const PACHINKO_BACKGROUND := Color("14121f")
const RAIL_COLOR := Color("c9c3d6")
const GUTTER_COLOR := Color("000000")
const PIN_COLOR := Color("d8dbe2")
const SPECIAL_COLOR := Color("ffc83d")
const POCKET_COLOR := Color("3fa7d6", 0.55)
const MAZE_BACKGROUND := Color("ede6e3")
const WALL_COLOR := Color("36382e")
const GOAL_COLOR := Color("7d82b8")
const HOLE_COLOR := Color("000000")
const BALL_COLOR := Color("f06449")
## Pixels of dash and gap on the goal's dashed circle.
const DASH := 8.0
## Smallest radius a pin is drawn with on screen, in screen pixels (thumbnails stay legible).
const MIN_PIN_PIXELS := 0.9
## How far the drawn ring (and gutter) reach outside `ring_radius`, in pixels.
const RING_OVERHANG := 8.0
## How strongly the machine's art shows behind the pins (1 = as in the game).
const ART_STRENGTH := 0.6


## Draws `level` on `canvas` through `xform`. `layers` picks what to draw.
static func draw_board(
	canvas: CanvasItem,
	level: BoardLevel,
	xform: Transform2D = Transform2D.IDENTITY,
	layers: int = Layer.ALL
) -> void:
	if canvas == null or level == null:
		return
	canvas.draw_set_transform_matrix(xform)
	if layers & Layer.BACKGROUND:
		if level.is_maze():
			canvas.draw_rect(board_bounds(level), MAZE_BACKGROUND)
		else:
			_draw_machine(canvas, level)
	if level.is_pachinko():
		var pixels_per_unit := maxf(xform.get_scale().x, 1e-3)
		_draw_pachinko(canvas, level, layers, MIN_PIN_PIXELS / pixels_per_unit)
	else:
		_draw_maze(canvas, level, layers)
	canvas.draw_set_transform_matrix(Transform2D.IDENTITY)


## Draws the whole board scaled to fit inside `rect` (for thumbnails), keeping its aspect.
static func draw_thumbnail(
	canvas: CanvasItem, level: BoardLevel, rect: Rect2, layers: int = Layer.ALL
) -> void:
	if level == null:
		return
	draw_board(canvas, level, fit_transform(level, rect), layers)


## Everything the painter draws for `level`, in board pixels: the board's area plus what
## overhangs it (maze walls on the edge reach half a wall outside; the ring's rim).
static func board_bounds(level: BoardLevel) -> Rect2:
	var bounds := Rect2(Vector2.ZERO, level.size)
	if level.is_maze() and is_finite(level.wall_width) and level.wall_width > 0.0:
		bounds = bounds.grow(level.wall_width * 0.5)
	elif level.is_pachinko() and level.ring_center.is_finite() and is_finite(level.ring_radius):
		var rim := level.ring_radius + RING_OVERHANG
		bounds = bounds.merge(Rect2(level.ring_center - Vector2.ONE * rim, Vector2.ONE * rim * 2.0))
	return bounds


## The board → canvas transform that fits `board_bounds` into `rect`, centred.
static func fit_transform(level: BoardLevel, rect: Rect2, margin: float = 0.0) -> Transform2D:
	var area := rect.grow(-margin)
	if level == null:
		return Transform2D(0.0, area.position)
	var bounds := board_bounds(level)
	var size := bounds.size
	if size.x <= 0.0 or size.y <= 0.0 or not size.is_finite():
		return Transform2D(0.0, area.position)
	var scale := minf(area.size.x / size.x, area.size.y / size.y)
	var offset := area.position + (area.size - size * scale) * 0.5 - bounds.position * scale
	return Transform2D(0.0, Vector2(scale, scale), 0.0, offset)


static func _draw_pachinko(
	canvas: CanvasItem, level: BoardLevel, layers: int, min_pin_radius: float
) -> void:
	var c := level.ring_center
	var r := level.ring_radius
	if not c.is_finite() or not is_finite(r) or r <= 0.0:
		return
	if layers & Layer.RING:
		var ring := FasciaBook.palette_of(level.fascia).ring.lightened(0.15)
		canvas.draw_arc(c, r + 3.0, 0.0, TAU, 128, ring, 6.0)
	if layers & Layer.GUTTER:
		# The gutter is a black gap cut into the ring, with its ends marked.
		var from := deg_to_rad(level.gutter_start_deg)
		var to := deg_to_rad(level.gutter_end_deg)
		canvas.draw_arc(c, r + 3.0, from, to, 24, GUTTER_COLOR, 8.0)
		for angle: float in [from, to]:
			var direction := Vector2.from_angle(angle)
			canvas.draw_line(c + direction * r, c + direction * (r + 8.0), RAIL_COLOR, 2.0)
	if layers & Layer.RAIL:
		var guide := LaunchRail.guide_points(level)
		canvas.draw_polyline(guide, RAIL_COLOR, LaunchRail.GUIDE_WALL_RADIUS * 2.0)
		var stop := LaunchRail.stopper(level)
		canvas.draw_line(stop[0], stop[1], RAIL_COLOR, LaunchRail.GUIDE_WALL_RADIUS * 2.0)
		var deflector := LaunchRail.deflector(level)
		canvas.draw_line(deflector[0], deflector[1], RAIL_COLOR, LaunchRail.GUIDE_WALL_RADIUS * 2.0)
		canvas.draw_circle(deflector[1], LaunchRail.GUIDE_WALL_RADIUS, RAIL_COLOR)
		canvas.draw_circle(
			LaunchRail.launch_position(level), level.ball_radius, BALL_COLOR, false, 1.0
		)
	if layers & Layer.POCKETS:
		for spec in level.pockets:
			if spec != null:
				_draw_pocket(canvas, spec, level.pin_radius)
	if layers & Layer.BONUS:
		BonusPainter.draw_all(canvas, level)
	if layers & Layer.PINS:
		_draw_pins(canvas, level, min_pin_radius)
	if layers & Layer.WINDMILLS:
		for spec in level.windmills:
			WindmillPainter.draw_wheel(canvas, spec, 0.0)


# The machine's plate under the whole board and its art, faded, inside the ring.
static func _draw_machine(canvas: CanvasItem, level: BoardLevel) -> void:
	var palette := FasciaBook.palette_of(level.fascia)
	canvas.draw_rect(board_bounds(level), palette.plate.lerp(PACHINKO_BACKGROUND, 0.3))
	var r := level.ring_radius
	if not level.ring_center.is_finite() or not is_finite(r) or r <= 0.0:
		return
	var art := FasciaBook.art_of(palette)
	if art != null:
		var disc := Rect2(level.ring_center - Vector2(r, r), Vector2(r, r) * 2.0)
		var tint := palette.art_tint
		canvas.draw_texture_rect(art, disc, false, Color(tint, ART_STRENGTH))


static func _draw_pocket(canvas: CanvasItem, spec: PocketSpec, pin_radius: float) -> void:
	var half := spec.width * 0.5 + pin_radius
	var bottom := spec.position + Vector2(0.0, spec.depth - spec.width * 0.5)
	var cup := PackedVector2Array()
	cup.append(spec.position + Vector2(-half, 0.0))
	for i in 13:
		var angle := PI - PI * float(i) / 12.0
		cup.append(bottom + Vector2(cos(angle), sin(angle)) * half)
	cup.append(spec.position + Vector2(half, 0.0))
	if cup.size() >= 3 and spec.depth >= spec.width * 0.5:
		canvas.draw_colored_polygon(cup, POCKET_COLOR)


static func _draw_pins(canvas: CanvasItem, level: BoardLevel, min_radius: float) -> void:
	var r := maxf(level.pin_radius, min_radius)
	for i in level.pins.size():
		var p := level.pins[i]
		if i < level.pin_special.size() and level.pin_special[i] != 0:
			var d := r * 2.2
			var diamond := PackedVector2Array(
				[p + Vector2(0, -d), p + Vector2(d, 0), p + Vector2(0, d), p + Vector2(-d, 0)]
			)
			canvas.draw_colored_polygon(diamond, SPECIAL_COLOR)
		else:
			canvas.draw_circle(p, r, PIN_COLOR)


static func _draw_maze(canvas: CanvasItem, level: BoardLevel, layers: int) -> void:
	_draw_painted_items(canvas, level, layers)
	if layers & Layer.GOAL and level.goal_radius > 0.0:
		_draw_dashed_circle(canvas, level.goal_center, level.goal_radius, GOAL_COLOR, 5.0)
	if layers & Layer.HOLES:
		for hole in level.holes:
			canvas.draw_circle(hole, level.hole_radius, HOLE_COLOR)
	if layers & Layer.WALLS:
		var half := level.wall_width * 0.5
		@warning_ignore("integer_division")  # walls are stored as point pairs
		for w in level.walls.size() / 2:
			var a := level.walls[w * 2]
			var b := level.walls[w * 2 + 1]
			canvas.draw_line(a, b, WALL_COLOR, level.wall_width)
			canvas.draw_circle(a, half, WALL_COLOR)
			canvas.draw_circle(b, half, WALL_COLOR)
	if layers & Layer.STARTS:
		for start in level.ball_starts:
			canvas.draw_circle(start, level.ball_radius, BALL_COLOR)


# The items whose rows draw them (ItemKind.paints: a floor arrow), under everything else.
static func _draw_painted_items(canvas: CanvasItem, level: BoardLevel, layers: int) -> void:
	for kind in ItemKinds.of_game(level.kind):
		var flag: int = Layer.get(kind.paint_layer, 0)
		if kind.paints.is_valid() and layers & flag:
			for index in kind.field_indices(level):
				if kind.is_item(level, index):
					kind.paints.call(canvas, level, index)


static func _draw_dashed_circle(
	canvas: CanvasItem, center: Vector2, radius: float, color: Color, width: float
) -> void:
	var circumference := TAU * radius
	var dashes := maxi(4, floori(circumference / (DASH * 2.0)))
	var step := TAU / float(dashes)
	for i in dashes:
		var from := step * i
		canvas.draw_arc(center, radius, from, from + step * 0.5, 6, color, width)
