extends SceneTree
## Builds the four original boards with the board editor's own actions (the operations its
## tools commit: pin patterns, pocket stamps, walls, erase, mirror mode) on a fresh
## BoardLevel, checks each with BoardValidator, and saves it with its level scene:
##   tools/godot.sh --headless --path . -s res://tools/make_original_boards.gd
## pachinko/tulips: a dense lattice with four tulips and three plain pockets.
## pachinko/windmills: an open board of pin rows, five windmills and a few rich pockets.
## maze/first_roll, maze/two_together: the first boards, one ball then two in a folding corridor.
## maze/catacombs: 12 x 9 twisting corridors with black holes in the dead ends.
## maze/courtyards: wide square rings round the goal with chicanes, built in mirror mode.

const ActionHistory := preload("res://addons/board_editor/core/action_history.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const SetPropertiesAction := preload("res://addons/board_editor/actions/set_properties_action.gd")
const PatternAction := preload("res://addons/board_editor/actions/pattern_action.gd")
const PocketAction := preload("res://addons/board_editor/actions/pocket_action.gd")
const WallAction := preload("res://addons/board_editor/actions/wall_action.gd")
const AddItemsAction := preload("res://addons/board_editor/actions/add_items_action.gd")
const DeleteItemsAction := preload("res://addons/board_editor/actions/delete_items_action.gd")
const Mirror := preload("res://addons/board_editor/core/mirror.gd")
const NewBoard := preload("res://addons/board_editor/core/new_board.gd")
const MakeOriginalMazes := preload("res://tools/make_original_mazes.gd")
const BonusActions := preload("res://addons/board_editor/bonus/bonus_actions.gd")

const CENTER := 350.0
## Balls in the cup at the start (issue 41): enough for a session of minutes at a steady
## pace (`--sessions=20 --seed=1`, pachinko rules 5: 40 balls gave a median of 215 s and a
## 10th percentile of 91 s; 50 give 262 s and 143 s).
const TULIPS_CUP := 50
const WINDMILLS_CUP := 60
## A level scene: one BoardNode showing the board file.
const SCENE_TEXT := """[gd_scene load_steps=3 format=3]

[ext_resource type="Script" path="res://scenes/board_view/board_node.gd" id="1_node"]
[ext_resource type="Resource" path="%s" id="2_level"]

[node name="Board" type="Node2D"]
script = ExtResource("1_node")
level = ExtResource("2_level")
"""


func _initialize() -> void:
	var ok := true
	for board: BoardLevel in [make_tulips(), make_windmills()]:
		ok = _save(board) and ok
	for board: BoardLevel in [
		MakeOriginalMazes.make_first_roll(),
		MakeOriginalMazes.make_two_together(),
		MakeOriginalMazes.make_catacombs(),
		MakeOriginalMazes.make_courtyards()
	]:
		ok = _save(board) and ok
	quit(0 if ok else 1)


## Tulip Garden: a dense staggered lattice with four tulips (the bonus layer's tulip: its
## wings open after a catch, so it catches more, and shut after the next) in cleared beds
## on the flanks, and three plain pockets down the middle and on the lower flanks.
static func make_tulips() -> BoardLevel:
	var history := ActionHistory.new()
	var level := pachinko_base(
		history,
		"tulips",
		"Tulip Garden",
		"A dense field of pins with four tulips: a catch opens a tulip's petals for the next ball."
	)
	level.fascia = "garden"
	level.cup_start_balls = TULIPS_CUP
	var axis := CENTER
	history.commit(PatternAction.new(level, _lattice(27, 22.0, 31), Vector2(CENTER, CENTER)))
	erase_pins_outside_field(history, level, 22.0)
	# Plain pockets [mouth, payout]; the ones off the centre line are mirrored to the right.
	# (Payouts re-tuned so no held handle strength pays much more than another: the pair low
	# on the flanks 4, the top 2; tools/power_returns.gd.)
	for pocket: Array in [[Vector2(350, 280), 2], [Vector2(280, 470), 4], [Vector2(350, 590), 3]]:
		var mouth: Vector2 = pocket[0]
		erase_pins_in(history, level, Rect2(mouth - Vector2(40, 34), Vector2(80, 78)), axis)
		history.commit(PocketAction.new(level, mouth, 22.0, 24.0, pocket[1], axis))
	# Tulips, each mirrored: high on the flanks and lower out wide.
	# [mouth, payout]: the high pair catches a middle strength's every ball, so it pays 1.
	for tulip: Array in [[Vector2(220, 240), 1], [Vector2(170, 420), 4]]:
		var mouth: Vector2 = tulip[0]
		erase_pins_in(history, level, Rect2(mouth - Vector2(40, 34), Vector2(80, 78)), axis)
		var role := BonusPocketSpec.Role.TULIP
		var spec := BonusPocketSpec.of_role(role, mouth, 26.0, 26.0, tulip[1])
		history.commit(BonusActions.AddBonus.new(level, spec, axis))
	shape_launch(history, level, LaunchRail.AIMING_END_DEG)
	return level


## Windmills: staggered rows of pins with wide gaps, five real windmills (風車) in cleared
## circles (the top one and the lower pair driven, the middle pair free-spinning, each
## mirrored twin turning the other way), and three rich pockets under umbrella arcs.
static func make_windmills() -> BoardLevel:
	var history := ActionHistory.new()
	var level := pachinko_base(
		history,
		"windmills",
		"Windmills",
		(
			"Five windmills turn in an open field: their blades fling balls toward two ×8"
			+ " pockets low down and a ×1 pocket in the middle."
		)
	)
	level.fascia = "country"
	level.cup_start_balls = WINDMILLS_CUP
	var axis := CENTER
	for row in 13:
		var row_pattern := {"kind": "row", "count": 17 - row % 2, "spacing": 34.0}
		var x := CENTER + (17.0 if row % 2 == 1 else 0.0)
		history.commit(PatternAction.new(level, row_pattern, Vector2(x, 130.0 + row * 36.0)))
	erase_pins_outside_field(history, level, 22.0)
	# (The middle pocket, under the strengths that pay most, pays 1, the low pair 8: no held
	# handle strength pays much more than another; tools/power_returns.gd.)
	for pocket: Array in [[Vector2(350, 390), 1], [Vector2(220, 560), 8]]:
		var mouth: Vector2 = pocket[0]
		erase_pins_in(history, level, Rect2(mouth - Vector2(45, 60), Vector2(90, 100)), axis)
		history.commit(PocketAction.new(level, mouth, 24.0, 26.0, pocket[1], axis))
		var umbrella := {"kind": "arc", "count": 5, "spacing": 14.0, "radius": 28.0}
		history.commit(PatternAction.new(level, umbrella, mouth + Vector2(-40, -10), axis))
	var wheels := BoardItems.empty_set()
	wheels["windmills"] = [
		WindmillSpec.driven(Vector2(350, 210), 6, 24.0, 150.0),
		WindmillSpec.spinning_free(Vector2(230, 330), 4, 22.0, 240.0),
		WindmillSpec.spinning_free(Vector2(470, 330), 4, 22.0, 240.0),
		WindmillSpec.driven(Vector2(262, 500), 3, 22.0, -110.0),
		WindmillSpec.driven(Vector2(438, 500), 3, 22.0, 110.0),
	]
	var wheel_list: Array = wheels["windmills"]
	for spec: WindmillSpec in wheel_list:
		erase_pins_near(history, level, spec.position, spec.sweep_radius() + 13.0)
	history.commit(AddItemsAction.new(level, wheels, "Add windmills"))
	shape_launch(history, level, LaunchRail.AIMING_END_DEG)
	return level


## Erases the field pins closer than `radius` to `centre` (a windmill's clearing: its sweep,
## a pin and a ball's width).
static func erase_pins_near(
	history: ActionHistory, level: BoardLevel, centre: Vector2, radius: float
) -> void:
	var doomed: Array[Vector2i] = []
	for i in level.pins.size():
		if level.pin_pocket[i] < 0 and level.pins[i].distance_to(centre) < radius:
			doomed.append(BoardItems.make(BoardItems.Kind.PIN, i))
	if not doomed.is_empty():
		history.commit(DeleteItemsAction.new(level, doomed))


## Opens the rail at `rail_end_deg` and erases the free pins in the flight lane under the
## top of the ring, so launch power decides where a ball lands (see LaunchRail).
static func shape_launch(history: ActionHistory, level: BoardLevel, rail_end_deg: float) -> void:
	history.commit(SetPropertiesAction.new(level, {"rail_end_deg": rail_end_deg}, "Board settings"))
	var doomed: Array[Vector2i] = []
	for i in level.pins.size():
		if level.pin_pocket[i] < 0 and LaunchRail.in_flight_lane(level, level.pins[i]):
			doomed.append(BoardItems.make(BoardItems.Kind.PIN, i))
	history.commit(DeleteItemsAction.new(level, doomed))


## A fresh pachinko board with the classic machine's ring, rail and gutter.
static func pachinko_base(
	history: ActionHistory, id: String, title: String, blurb: String
) -> BoardLevel:
	var level := BoardLevel.new()
	var settings := NewBoard.pachinko_settings(id, title, blurb)
	history.commit(SetPropertiesAction.new(level, settings, "Board settings"))
	return level


## Erases the field pins farther out than the launch rail's guide arc less `margin`.
static func erase_pins_outside_field(
	history: ActionHistory, level: BoardLevel, margin: float
) -> void:
	var field := LaunchRail.guide_radius(level) - margin
	var doomed: Array[Vector2i] = []
	for i in level.pins.size():
		if level.pin_pocket[i] < 0 and level.pins[i].distance_to(level.ring_center) > field:
			doomed.append(BoardItems.make(BoardItems.Kind.PIN, i))
	history.commit(DeleteItemsAction.new(level, doomed))


## Erases the field pins inside `rect` and inside its mirror image across `axis`.
static func erase_pins_in(
	history: ActionHistory, level: BoardLevel, rect: Rect2, axis: float
) -> void:
	var mirrored := Rect2(Vector2(2.0 * axis - rect.end.x, rect.position.y), rect.size)
	var doomed: Array[Vector2i] = []
	for i in level.pins.size():
		var p := level.pins[i]
		if level.pin_pocket[i] < 0 and (rect.has_point(p) or mirrored.has_point(p)):
			doomed.append(BoardItems.make(BoardItems.Kind.PIN, i))
	if not doomed.is_empty():
		history.commit(DeleteItemsAction.new(level, doomed))


static func _lattice(count: int, spacing: float, rows: int) -> Dictionary:
	return {"kind": "lattice", "count": count, "spacing": spacing, "rows": rows}


## Validates, saves the level and writes its scene; false (and the reasons) on failure.
static func _save(level: BoardLevel) -> bool:
	var kind := BoardLevel.kind_name(level.kind)
	var id := level.board_id.trim_prefix(kind + "_")
	var errors := BoardValidator.errors(level)
	var issues := BoardValidator.validate(level)
	print(
		(
			"%s: %d errors, %d warnings"
			% [level.board_id, errors.size(), issues.size() - errors.size()]
		)
	)
	for issue in issues.slice(0, 12):
		print("  %s" % issue)
	if not errors.is_empty():
		push_error("make_original_boards: %s has %d errors." % [level.board_id, errors.size()])
		return false
	var path := "res://levels/%s/%s.board" % [kind, id]
	MedalRule.keep_file_medals(level, path)
	# The file's uid lives in its .board.uid sidecar, which saving leaves alone.
	var error := ResourceSaver.save(level, path)
	if error != OK:
		push_error("make_original_boards: could not write %s (%s)" % [path, error_string(error)])
		return false
	var scene_path := "res://scenes/boards/%s_%s.tscn" % [kind, id]
	var scene := FileAccess.open(scene_path, FileAccess.WRITE)
	if scene == null:
		var problem := error_string(FileAccess.get_open_error())
		push_error("make_original_boards: could not write %s (%s)" % [scene_path, problem])
		return false
	# Written as text so rebuilding the boards leaves unchanged scenes byte for byte.
	scene.store_string(SCENE_TEXT % path)
	scene.close()
	print(
		(
			"wrote %s (%d pins, %d pockets, %d walls, %d holes) and %s"
			% [
				path,
				level.pins.size(),
				level.pockets.size(),
				level.walls.size() / 2,
				level.holes.size(),
				scene_path
			]
		)
	)
	return true
