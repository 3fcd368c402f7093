extends GutTest
## Text that came from a file is never parsed as markup: a board whose name, description or
## field names hold BBCode ([img], [font], [url], [color]) shows those tags literally on every
## panel that prints them and loads nothing they point at (tests/fixtures/hostile_markup/).

const InstructionsScene := preload("res://scenes/pachinko/instructions_panel.tscn")
const GameScene := preload("res://scenes/pachinko/pachinko_game.tscn")
const ROOT := "res://tests/fixtures/hostile_markup/"
const PAYLOAD := ROOT + "payload.tres"
const RAN := &"hostile_markup_payload_ran"
## Each name fixture's display name is one tag; every fixture's description holds all four.
const NAMED := {
	"name_img.board": "[img]" + PAYLOAD + "[/img]",
	"name_font.board": "[font=" + PAYLOAD + "]F[/font]",
	"name_url.board": "[url=https://example.invalid]U[/url]",
	"name_color.board": "[color=red]C[/color]",
}
## Where the game-scene tests put their board: My boards, the only folder besides levels/.
const USER_BOARD := "user://boards/pachinko/zz_test_markup_hostile.board"

## Every script or scene that makes a BBCode label, reviewed: only the instructions panel
## shows file text (escaped above); the stats panel shows numbers only, the rules reminder
## key names only. A new one must be checked the same way and added here.
const REVIEWED_BBCODE := [
	"res://scenes/pachinko/hud/rules_reminder.gd",
	"res://scenes/pachinko/hud/stats_panel.gd",
	"res://scenes/pachinko/instructions_panel.gd",
	"res://scenes/pachinko/instructions_panel.tscn",
]


func before_each() -> void:
	Engine.remove_meta(RAN)


func after_all() -> void:
	DirAccess.remove_absolute(ProjectSettings.globalize_path(USER_BOARD))
	App.request_board("pachinko", "res://levels/pachinko/classic.board")


func _level(fixture: String) -> BoardLevel:
	var loaded := BoardLoader.load_board(ROOT + fixture, [ROOT])
	assert_eq(loaded.error, "", fixture + " is a playable board")
	return loaded.level


func _panel() -> InstructionsPanel:
	var panel := InstructionsScene.instantiate() as InstructionsPanel
	add_child_autofree(panel)
	return panel


func _body(panel: Node) -> RichTextLabel:
	return panel.get_node("Card/Margin/Box/Body") as RichTextLabel


func _assert_literal(shown: String, where: String, tags: Array = NAMED.values()) -> void:
	for tag: String in tags:
		assert_string_contains(shown, tag, where + " shows the tag as typed")
	assert_false(Engine.has_meta(RAN), where + ": nothing the tags name was loaded")
	assert_false(ResourceLoader.has_cached(PAYLOAD), where + ": the payload is not in the cache")


func test_the_escape_helper_keeps_every_bracket_literal() -> void:
	var label := RichTextLabel.new()
	label.bbcode_enabled = true
	add_child_autofree(label)
	var text := "".join(NAMED.values()) + " [lb] [/b] [[b]] ]["
	label.text = PlainMarkup.escape(text)
	assert_eq(label.get_parsed_text(), text)
	_assert_literal(label.get_parsed_text(), "a label with escaped text")


func test_the_name_shows_literally_on_the_start_panel() -> void:
	for fixture: String in NAMED:
		var panel := _panel()
		panel.show_start(_level(fixture))
		var title := panel.get_node("Card/Margin/Box/Title") as Label
		assert_string_contains(title.text, NAMED[fixture], fixture + ": the title is a plain label")
		_assert_literal(_body(panel).get_parsed_text(), fixture + " start", [])


func test_the_name_shows_literally_on_the_game_over_panel() -> void:
	for fixture: String in NAMED:
		var panel := _panel()
		var summary := {"game_shots": 3, "game_payouts": 4}
		panel.show_game_over(_level(fixture), summary, 12, false)
		var shown := _body(panel).get_parsed_text()
		_assert_literal(shown, fixture + " game over", [NAMED[fixture]])
		assert_string_contains(shown, "Best game on %s: +12" % NAMED[fixture])


func test_a_refusal_quoting_a_field_name_shows_literally() -> void:
	var loaded := BoardLoader.load_board(ROOT + "markup_field.board", [ROOT])
	assert_null(loaded.level, "an unknown field is refused")
	var panel := _panel()
	panel.show_problem(loaded.error)
	_assert_literal(_body(panel).get_parsed_text(), "the problem panel")


func _copy_to_my_boards(fixture: String) -> void:
	DirAccess.make_dir_recursive_absolute(USER_BOARD.get_base_dir())
	var file := FileAccess.open(USER_BOARD, FileAccess.WRITE)
	file.store_buffer(FileAccess.get_file_as_bytes(ROOT + fixture))
	file.close()
	App.request_board("pachinko", USER_BOARD)


func test_the_game_scene_shows_a_named_board_literally() -> void:
	_copy_to_my_boards("name_font.board")
	var game := GameScene.instantiate() as Control
	add_child_autofree(game)
	assert_not_null(game.get("rules"), "the board plays")
	_assert_literal(_body(game.get_node("Instructions")).get_parsed_text(), "the game's panel", [])
	var title := (game as PachinkoGame).title
	assert_eq(title.text, NAMED["name_font.board"], "the HUD title is a plain label")


func test_the_game_scene_shows_a_refused_field_name_literally() -> void:
	_copy_to_my_boards("markup_field.board")
	var game := GameScene.instantiate() as Control
	add_child_autofree(game)
	assert_push_error("Pachinko")
	assert_null(game.get("rules"), "nothing to play")
	_assert_literal(_body(game.get_node("Instructions")).get_parsed_text(), "the refusal")


func test_every_bbcode_label_is_a_reviewed_one() -> void:
	var found: Array[String] = []
	for root in ["res://scenes", "res://addons/board_editor", "res://scripts"]:
		_collect_bbcode(root, found)
	found.sort()
	assert_eq(found, REVIEWED_BBCODE)


func _collect_bbcode(folder: String, found: Array[String]) -> void:
	for sub in DirAccess.get_directories_at(folder):
		_collect_bbcode(folder.path_join(sub), found)
	for file_name in DirAccess.get_files_at(folder):
		if not (file_name.ends_with(".gd") or file_name.ends_with(".tscn")):
			continue
		var text := FileAccess.get_file_as_string(folder.path_join(file_name))
		for marker in ["RichTextLabel", "bbcode", "append_text", "print_rich"]:
			if text.contains(marker):
				found.append(folder.path_join(file_name))
				break
