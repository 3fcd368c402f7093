class_name GoldPinsText
extends RefCounted
## The gold pins in words: the side panel's one line (shown in a label of its own under
## the panel, made on first use), the start card's sentence and the prize's announcement.
## Plain text except the card's sentence, which is the card's own BBCode.

## The side panel's label's font size (the panel's numbers are 15).
const FONT_SIZE := 15
const COLOUR := Color("ffd54a")


## The side panel's line for `rules`' game: "Gold pins 5 left → Gold spin", or the rush's
## seconds while one is on.
static func panel_line(rules: PachinkoRules) -> String:
	var gold := rules.gold
	if gold.rush_on():
		return "Gold rush: double pay, %d s left" % ceili(gold.rush_left)
	if gold.pins.is_empty():  # before the first game: its set lights as it starts
		return "Gold pins: hit them all → %s" % prize_name(rules.bonus.has_reels())
	return "Gold pins %d left → %s" % [gold.left(), prize_name(rules.bonus.has_reels())]


## "Gold spin" on a machine with reels, else "Gold rush".
static func prize_name(spin: bool) -> String:
	return "Gold spin" if spin else "Gold rush"


## The start card's sentence for `level` (BBCode).
static func card_line(level: BoardLevel) -> String:
	var spin := false
	for spec in level.bonus_pockets:
		spin = spin or spec.role == BonusPocketSpec.Role.START
	var prize := (
		"a [b]Gold spin[/b] (always a reach)"
		if spin
		else "a [b]Gold rush[/b] (double pay for %d s)" % int(GoldPins.RUSH_SECONDS)
	)
	return "[b]Gold pins:[/b] each one you hit adds a ball; hit them all for %s." % prize


## The prize's announcement: title and line under it.
static func announcement(spin: bool) -> PackedStringArray:
	if spin:
		return PackedStringArray(["GOLD SPIN!", "all gold pins hit: a reach for sure"])
	return PackedStringArray(
		["GOLD RUSH!", "every pocket pays double for %d s" % int(GoldPins.RUSH_SECONDS)]
	)


## Shows the panel's line for `rules` in a label just under `panel` (made on first use).
static func show_under(panel: Control, rules: PachinkoRules) -> void:
	if panel == null or panel.get_parent() == null or rules == null:
		return
	var parent := panel.get_parent()
	var label := parent.get_node_or_null(^"GoldPinsLine") as Label
	if label == null:
		label = Label.new()
		label.name = "GoldPinsLine"
		label.add_theme_font_size_override(&"font_size", FONT_SIZE)
		label.add_theme_color_override(&"font_color", COLOUR)
		parent.add_child(label)
		parent.move_child(label, panel.get_index() + 1)
	label.text = panel_line(rules)
