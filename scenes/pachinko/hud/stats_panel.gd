extends PanelContainer
## Session numbers: shots, where the balls went, hits per pocket and the payout ratio.

var _text: RichTextLabel


func _ready() -> void:
	_text = RichTextLabel.new()
	_text.bbcode_enabled = true
	_text.fit_content = true
	_text.scroll_active = false
	_text.autowrap_mode = TextServer.AUTOWRAP_WORD_SMART
	_text.custom_minimum_size = Vector2(10, 0)
	_text.add_theme_font_size_override("normal_font_size", 15)
	_text.add_theme_font_size_override("bold_font_size", 15)
	add_child(_text)


## Shows `stats` (PachinkoRules.stats()).
func show_stats(stats: Dictionary) -> void:
	if _text == null:
		return
	var hits: Array = stats.get("pocket_hits", [])
	var pocket_line := ""
	for i in hits.size():
		var count: int = hits[i]
		pocket_line += "%s[b]%d[/b]" % ["" if i == 0 else "  ", count]
	if pocket_line.is_empty():
		pocket_line = "none"
	var ratio: float = stats.get("payout_ratio", 0.0)
	var lines := PackedStringArray(
		[
			(
				"[b]Shots[/b] %d    [b]In play[/b] %d"
				% [stats.get("shots", 0), stats.get("in_play", 0)]
			),
			(
				"[b]Won[/b] %d    [b]Drained[/b] %d    [b]Back[/b] %d"
				% [stats.get("won", 0), stats.get("drained", 0), stats.get("returned", 0)]
			),
			"[b]Pocket hits[/b]  %s" % pocket_line,
			"[b]Paid out[/b] %d balls    [b]Ratio[/b] %.2f" % [stats.get("payouts", 0), ratio],
			(
				"[color=#8fe39a]Every ball accounted for[/color]"
				if stats.get("accounting_ok", false)
				else "[color=#ff7a7a]Ball count mismatch[/color]"
			),
		]
	)
	_text.text = "\n".join(lines)
