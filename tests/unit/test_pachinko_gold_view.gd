extends GutTest
## The gold pins on screen: the side panel's line names what is left and the prize, a pin
## put out bursts, and the start card's sentence names the machine's prize.

const CLASSIC := "res://levels/pachinko/classic.board"
const FEVER := "res://levels/pachinko/fever.board"


func _rules(path: String) -> PachinkoRules:
	var level := BoardLoader.load_board(path).level.duplicate(true) as BoardLevel
	var rules := PachinkoRules.new(level, 1)
	rules.start_game()
	return rules


func test_the_panel_line_counts_down_and_names_the_prize() -> void:
	var rules := _rules(CLASSIC)
	var count := rules.gold.pins.size()
	assert_eq(GoldPinsText.panel_line(rules), "Gold pins %d left → Gold rush" % count)
	rules.world.pin_hit.emit(rules.fire(50.0), rules.gold.pins[0], 100.0)
	assert_eq(GoldPinsText.panel_line(rules), "Gold pins %d left → Gold rush" % (count - 1))
	rules.gold.start_rush()
	assert_eq(GoldPinsText.panel_line(rules), "Gold rush: double pay, 20 s left")
	assert_string_contains(GoldPinsText.panel_line(_rules(FEVER)), "→ Gold spin")


func test_before_the_game_the_line_shows_no_count() -> void:
	var level := BoardLoader.load_board(CLASSIC).level.duplicate(true) as BoardLevel
	var waiting := PachinkoRules.new(level, 1)
	assert_eq(GoldPinsText.panel_line(waiting), "Gold pins: hit them all → Gold rush")


func test_the_card_names_the_prize() -> void:
	var classic := BoardLoader.load_board(CLASSIC).level
	var fever := BoardLoader.load_board(FEVER).level
	assert_string_contains(GoldPinsText.card_line(classic), "Gold rush")
	assert_string_contains(GoldPinsText.card_line(fever), "Gold spin")


func test_a_pin_put_out_bursts() -> void:
	var rules := _rules(CLASSIC)
	var layer := GoldPinLayer.new()
	add_child_autofree(layer)
	layer.bind(rules, null)
	rules.world.pin_hit.emit(rules.fire(50.0), rules.gold.pins[0], 100.0)
	assert_eq(layer.bursts(), 1)
	layer._process(GoldPinLayer.BURST_SECONDS + 0.1)
	assert_eq(layer.bursts(), 0, "the burst is over")
	assert_eq(layer.aimed_pins().size(), 0, "nobody aims: no rings")
