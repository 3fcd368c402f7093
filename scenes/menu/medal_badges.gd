extends Control
## A level card's medal row: one disc per mode (easy, hard) in gold, silver or bronze, or an
## empty ring with no medal yet; on a locked board, a padlock and what opens it instead.

const COLORS := {
	Medals.Medal.GOLD: Color("#f2c14e"),
	Medals.Medal.SILVER: Color("#c9d1d9"),
	Medals.Medal.BRONZE: Color("#cd7f4a"),
}
const FAINT := Color(1, 1, 1, 0.45)
const RADIUS := 10.0
const FONT_SIZE := 16

## Medal in easy and in hard mode (Medals.Medal).
var easy_medal := Medals.Medal.NONE
var hard_medal := Medals.Medal.NONE
## A locked board shows a padlock and this text (what opens it) instead of medals.
var lock_text := ""


func _init() -> void:
	custom_minimum_size = Vector2(0, RADIUS * 2.0 + 6.0)
	mouse_filter = Control.MOUSE_FILTER_IGNORE


## Shows these medals, or the padlock and `locked_because` when that is not empty.
func show_medals(easy: Medals.Medal, hard: Medals.Medal, locked_because: String) -> void:
	easy_medal = easy
	hard_medal = hard
	lock_text = locked_because
	if lock_text.is_empty():
		tooltip_text = "Easy: %s · Hard: %s" % [Medals.name_of(easy), Medals.name_of(hard)]
	else:
		tooltip_text = lock_text
	queue_redraw()


func _draw() -> void:
	var mid := size.y * 0.5
	if not lock_text.is_empty():
		_draw_padlock(Vector2(RADIUS, mid))
		_draw_text(Vector2(RADIUS * 2.0 + 8.0, mid + 6.0), lock_text)
		return
	var x := RADIUS
	for entry: Array in [["Easy", easy_medal], ["Hard", hard_medal]]:
		var medal: int = entry[1]
		var centre := Vector2(x, mid)
		if COLORS.has(medal):
			var colour: Color = COLORS[medal]
			draw_circle(centre, RADIUS, colour)
			draw_circle(centre, RADIUS * 0.55, Color(1, 1, 1, 0.35), false, 2.0)
		else:
			draw_circle(centre, RADIUS - 1.0, FAINT, false, 2.0)
		var label: String = entry[0]
		_draw_text(Vector2(x + RADIUS + 6.0, mid + 6.0), label)
		x += 96.0


func _draw_text(at: Vector2, text: String) -> void:
	var font := get_theme_default_font()
	draw_string(font, at, text, HORIZONTAL_ALIGNMENT_LEFT, -1, FONT_SIZE, FAINT)


func _draw_padlock(centre: Vector2) -> void:
	draw_arc(centre + Vector2(0, -3), 5.5, PI, TAU, 12, FAINT, 2.5)
	draw_rect(Rect2(centre + Vector2(-8, -2), Vector2(16, 12)), FAINT)
