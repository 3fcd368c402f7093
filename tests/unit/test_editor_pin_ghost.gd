extends GutTest
## A ghost pin turns red wherever a click would give the board an error, not only where it
## would crowd a pin: outside the ring and in the launch rail too. Before, only crowding was
## asked, so a pin ghost beyond the ring stayed green and the click then gave "Pin 870 at
## (620, 40) is outside the ring." (seen in the editor on Tulip Garden).

const HitTest := preload("res://addons/board_editor/core/hit_test.gd")
const NewBoard := preload("res://addons/board_editor/core/new_board.gd")
const AddItemsAction := preload("res://addons/board_editor/actions/add_items_action.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")


func _errors_after_pin(level: BoardLevel, at: Vector2) -> int:
	var trial := level.duplicate_level()
	var data := BoardItems.empty_set()
	data["pins"] = PackedVector2Array([at])
	AddItemsAction.new(trial, data, "Try").do()
	return BoardValidator.errors(trial).size()


func test_a_pin_ghost_outside_the_ring_is_red() -> void:
	var level := NewBoard.make(BoardLevel.Kind.PACHINKO)
	var outside := level.ring_center + Vector2(level.ring_radius * 0.7, -level.ring_radius * 0.9)
	assert_gt(_errors_after_pin(level, outside), 0, "the click gives the board an error")
	assert_true(HitTest.pin_blocked(level, outside), "so the ghost is red")


func test_a_pin_ghost_in_the_launch_rail_is_red() -> void:
	var level := NewBoard.make(BoardLevel.Kind.PACHINKO)
	var middle := deg_to_rad((level.rail_start_deg + level.rail_end_deg) * 0.5)
	var in_rail := level.ring_center + Vector2.from_angle(middle) * (level.ring_radius - 12.0)
	assert_gt(_errors_after_pin(level, in_rail), 0, "the click gives the board an error")
	assert_true(HitTest.pin_blocked(level, in_rail), "so the ghost is red")


func test_a_pin_ghost_in_open_field_stays_green_and_crowding_still_counts() -> void:
	var level := NewBoard.make(BoardLevel.Kind.PACHINKO)
	var open := level.ring_center + Vector2(0, -120)
	assert_eq(_errors_after_pin(level, open), 0)
	assert_false(HitTest.pin_blocked(level, open))
	var data := BoardItems.empty_set()
	data["pins"] = PackedVector2Array([open])
	AddItemsAction.new(level, data, "Add").do()
	assert_true(HitTest.pin_blocked(level, open + Vector2(4, 0)), "on top of a pin")
