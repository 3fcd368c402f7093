extends GutTest
## One section of the level select (scenes/menu/card_section.gd): a file that loads before
## its card is made fills that card as it is made, and showing finished loads at once drops
## the cards still waiting to be made (they would land among the new ones otherwise).

const PATHS: Array[String] = [
	"res://levels/pachinko/classic.board",
	"res://levels/pachinko/fever.board",
	"res://levels/pachinko/windmills.board",
]

var _grid: GridContainer = null


func before_each() -> void:
	_grid = GridContainer.new()
	add_child_autofree(_grid)


func _jobs() -> Array[Dictionary]:
	var jobs: Array[Dictionary] = []
	for path in PATHS:
		jobs.append({"path": path, "kind": BoardLevel.Kind.PACHINKO, "root": "res://levels"})
	return jobs


func _card(index: int) -> LevelCard:
	return _grid.get_child(index).get("card") as LevelCard


func test_a_file_loaded_before_its_card_fills_the_card_as_it_is_made() -> void:
	var section := CardSection.new(_grid, false)
	var fills := [0]
	section.card_filled.connect(func() -> void: fills[0] += 1)
	section.start(PATHS, _jobs(), Callable(), 1)
	assert_eq(_grid.get_child_count(), 1, "one card made at once, the others wait")
	assert_true(section.has_pending_slots())
	# every file loads; the two with no card yet are kept for their cards (read back here)
	var early_all := func() -> bool:
		section.take_loaded(10)
		return section.waiting_results() == 2 and fills[0] == 1
	await wait_until(early_all, 20.0)
	assert_eq(fills[0], 1, "only the card that exists was filled")
	assert_true(section.is_loading(), "still loading while cards wait to be made")
	section.add_pending_slots(10)
	assert_eq(_grid.get_child_count(), 3)
	for index in 3:
		assert_false(_card(index).loading, "card %d filled as it was made" % index)
		assert_eq(_card(index).board_path, PATHS[index], "in listed order")
	assert_eq(fills[0], 3)
	section.take_loaded(10)
	assert_false(section.is_loading(), "done once every card is made and filled")


func test_showing_finished_loads_drops_the_cards_still_to_be_made() -> void:
	var section := CardSection.new(_grid, false)
	section.start(PATHS, _jobs(), Callable(), 1)
	var shown: Array[BoardLoadResult] = [BoardLoader.load_board(PATHS[2])]
	section.show_results(shown)
	assert_false(section.has_pending_slots(), "the old listing's cards are not made later")
	assert_false(section.is_loading(), "its loading was stopped")
	section.add_pending_slots(10)
	assert_eq(_grid.get_child_count(), 1)
	assert_eq(_card(0).board_path, PATHS[2])
	assert_false(_card(0).loading)
