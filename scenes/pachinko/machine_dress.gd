class_name MachineDress
extends RefCounted
## Dresses the pachinko screen around the board in its machine's colours (FasciaPalette): the
## cabinet behind everything, the side panel, its stats box, title and notes. The board
## itself dresses its own layers (BoardView). The scene's styles are shared by every copy of
## the scene, so each is duplicated before it is changed.


## Gives the pachinko screen `game` (pachinko_game.tscn) the look of `level`'s machine: its
## panel's `stats` box, `title` and `notes` are handed in by the screen, which knows where
## its layout put them (the portrait layout moves them).
static func apply(
	game: Control, level: BoardLevel, stats: Control, title: Label, notes: Label
) -> void:
	var palette := FasciaBook.palette_of(level.fascia)
	var backdrop := game.get_node_or_null(^"Backdrop") as CabinetBackdrop
	if backdrop != null:
		backdrop.dress(palette)
	var hud := game.get_node_or_null(^"Hud") as Control
	if hud != null:
		_restyle(hud, &"panel", palette.panel, palette.panel_border)
	if stats != null:
		_restyle(stats, &"panel", palette.box, palette.box_border)
	if title != null and title.label_settings != null:
		var settings := title.label_settings.duplicate() as LabelSettings
		settings.font_color = palette.title
		settings.outline_color = palette.title_outline
		title.label_settings = settings
	if notes != null:
		notes.add_theme_color_override(&"font_color", palette.notes)


# A copy of `control`'s flat style `style_name` in new colours.
static func _restyle(control: Control, style_name: StringName, face: Color, border: Color) -> void:
	var style := control.get_theme_stylebox(style_name) as StyleBoxFlat
	if style == null:
		return
	var dressed := style.duplicate() as StyleBoxFlat
	dressed.bg_color = face
	dressed.border_color = border
	control.add_theme_stylebox_override(style_name, dressed)
