extends GutTest
## The pattern tool's action: every pattern puts pins exactly where its settings say.

const PatternAction := preload("res://addons/board_editor/actions/pattern_action.gd")
const ActionHistory := preload("res://addons/board_editor/core/action_history.gd")
const TestEditorActions := preload("res://tests/unit/test_editor_actions.gd")


func assert_points(got: PackedVector2Array, want: Array, text: String) -> void:
	assert_eq(got.size(), want.size(), text + ": count")
	for i in mini(got.size(), want.size()):
		var expected: Vector2 = want[i]
		assert_almost_eq(got[i], expected, Vector2(0.001, 0.001), "%s: pin %d" % [text, i])


func test_row_is_centred_with_exact_spacing() -> void:
	var points := PatternAction.points_for(
		{"kind": "row", "count": 5, "spacing": 20.0}, Vector2(100, 50)
	)
	assert_points(
		points,
		[Vector2(60, 50), Vector2(80, 50), Vector2(100, 50), Vector2(120, 50), Vector2(140, 50)],
		"row"
	)


func test_lattice_rows_are_staggered_and_equilateral() -> void:
	var spacing := 20.0
	var points := PatternAction.points_for(
		{"kind": "lattice", "count": 3, "spacing": spacing, "rows": 3}, Vector2(0, 0)
	)
	var pitch := spacing * sqrt(3.0) * 0.5
	var want := [
		Vector2(-20, -pitch),
		Vector2(0, -pitch),
		Vector2(20, -pitch),
		Vector2(-10, 0),
		Vector2(10, 0),
		Vector2(-20, pitch),
		Vector2(0, pitch),
		Vector2(20, pitch),
	]
	assert_points(points, want, "lattice")
	assert_almost_eq(
		points[0].distance_to(points[3]), spacing, 0.001, "neighbours one spacing apart"
	)


func test_circle_neighbours_are_one_spacing_apart() -> void:
	var points := PatternAction.points_for(
		{"kind": "circle", "count": 8, "spacing": 15.0}, Vector2(200, 200)
	)
	assert_eq(points.size(), 8)
	assert_almost_eq(points[0], Vector2(200, 200 - 15.0 / (2.0 * sin(PI / 8))), Vector2.ONE * 0.001)
	for i in 8:
		assert_almost_eq(points[i].distance_to(points[(i + 1) % 8]), 15.0, 0.001)
		assert_almost_eq(
			points[i].distance_to(Vector2(200, 200)),
			points[0].distance_to(Vector2(200, 200)),
			0.001
		)


func test_arc_bows_up_symmetrically_with_exact_spacing() -> void:
	var centre := Vector2(300, 300)
	var points := PatternAction.points_for(
		{"kind": "arc", "count": 5, "spacing": 12.0, "radius": 40.0}, centre
	)
	assert_eq(points.size(), 5)
	assert_almost_eq(points[2], Vector2(300, 260), Vector2.ONE * 0.001, "middle pin straight up")
	for i in 4:
		assert_almost_eq(points[i].distance_to(points[i + 1]), 12.0, 0.001)
	assert_almost_eq(points[0].x - 300.0, 300.0 - points[4].x, 0.001, "symmetric")
	for point in points:
		assert_almost_eq(point.distance_to(centre), 40.0, 0.001)


func test_bad_settings_give_no_pins_and_an_error() -> void:
	var points := PatternAction.points_for(
		{"kind": "row", "count": 0, "spacing": 10.0}, Vector2.ZERO
	)
	assert_eq(points.size(), 0)
	assert_push_error("Pin pattern")


func test_mirrored_pattern_adds_the_reflection_once() -> void:
	var level := TestEditorActions.pachinko()
	var history := ActionHistory.new()
	var settings := {"kind": "row", "count": 3, "spacing": 10.0}
	history.commit(PatternAction.new(level, settings, Vector2(100, 100), 300.0))
	assert_eq(level.pins.size(), 6)
	assert_true(level.pins.has(Vector2(490, 100)), "the row's reflection across x = 300")
	history.commit(PatternAction.new(level, settings, Vector2(300, 200), 300.0))
	assert_eq(level.pins.size(), 9, "a row on the axis is its own mirror image")
