extends GutTest
## The house rules of docs/architecture.md ("## Layers"): every script keeps to its layer and
## no files need each other round a loop. The checker itself is tried on made-up breaches.

const LayerCheck := preload("res://tests/unit/layering/layer_check.gd")
const LayerList := preload("res://tests/unit/layering/layer_list.gd")
const ARCHITECTURE := "res://docs/architecture.md"
## The folders whose scripts are ours (addons/gut is unpacked by tools/setup.sh).
const ROOTS: Array[String] = ["scripts", "scenes", "addons", "tools", "tests"]
const SKIPPED: Array[String] = ["addons/gut"]

var _layers: LayerList


func before_all() -> void:
	_layers = LayerList.new(FileAccess.get_file_as_string(ARCHITECTURE))


func test_the_layer_list_is_read_from_the_architecture_page() -> void:
	assert_eq(_layers.problem, "")
	assert_gt(_layers.size(), 10)
	assert_eq(_layers.layer_of("scripts/physics/ball_world.gd"), 1)
	assert_eq(_layers.layer_of("tests/unit/test_layers.gd"), _layers.size())
	assert_lt(
		_layers.layer_of("scripts/board/board_level.gd"),
		_layers.layer_of("scripts/world/board_world_factory.gd")
	)
	# The most specific folder wins: autoplay sits above its game's rules.
	assert_gt(
		_layers.layer_of("scripts/maze/autoplay/maze_pilot.gd"),
		_layers.layer_of("scripts/maze/rules/maze_rules.gd")
	)


func test_every_script_keeps_to_its_layer_and_no_file_needs_itself() -> void:
	var files := {}
	for root in ROOTS:
		_read_scripts(root, files)
	assert_gt(files.size(), 300, "the scan found the project's scripts")
	var check := LayerCheck.new()
	var problems := check.check(files, _layers, _autoloads())
	assert_eq("\n".join(problems), "", "every breach of the layer list, one a line")
	assert_true(check.uses["scripts/board/board_level.gd"].has("scripts/board/pocket_spec.gd"))


func test_an_upward_use_is_named_with_both_files_and_the_line() -> void:
	var files := {
		"scripts/board/a.gd": "class_name A\nextends RefCounted\n\nvar b: B\n",
		"scripts/world/b.gd": "class_name B\nextends RefCounted\nvar a: A\n",
	}
	var problems := LayerCheck.new().check(files, _layers, {})
	assert_eq(
		Array(problems),
		[
			(
				"scripts/board/a.gd:4 uses scripts/world/b.gd, a higher layer: scripts/world/b.gd"
				+ " is in layer 4 (scripts/world/), scripts/board/a.gd in layer 2 (scripts/board/)"
			),
			(
				"file cycle: scripts/board/a.gd:4 uses scripts/world/b.gd, scripts/world/b.gd:3 uses"
				+ " scripts/board/a.gd"
			),
		]
	)


func test_a_loop_of_three_files_is_named_round_the_loop() -> void:
	var files := {
		"scripts/physics/a.gd": 'const C := preload("res://scripts/physics/c.gd")\n',
		"scripts/physics/b.gd": '\n\nextends "res://scripts/physics/a.gd"\n',
		"scripts/physics/c.gd": 'class_name C\nvar b := load("res://scripts/physics/b.gd")\n',
	}
	var check := LayerCheck.new()
	var problems := check.check(files, _layers, {})
	assert_eq(check.cycles.size(), 1)
	assert_eq(
		Array(problems),
		[
			(
				"file cycle: scripts/physics/a.gd:1 uses scripts/physics/c.gd, scripts/physics/c.gd:2"
				+ " uses scripts/physics/b.gd, scripts/physics/b.gd:3 uses scripts/physics/a.gd"
			),
		]
	)


func test_names_in_comments_strings_and_members_are_not_uses() -> void:
	var files := {
		"scripts/board/a.gd":
		(
			'extends RefCounted\n## Made by Top.\n# Top too\nvar s := "Top"\n'
			+ "var t := '''Top'''\nvar n := $Top\nvar m := self.Top\nvar x := 0xTop\n"
		),
		"scripts/app/top.gd": "class_name Top\n",
	}
	var check := LayerCheck.new()
	assert_eq(Array(check.check(files, _layers, {})), [])
	assert_eq(check.uses["scripts/board/a.gd"], {})


func test_an_autoload_named_below_its_layer_is_an_upward_use() -> void:
	var files := {
		"scripts/board/a.gd": "extends RefCounted\nfunc f() -> void:\n\tApp.go_to_menu()\n",
		"scenes/app/app.gd": "extends Node\n",
	}
	var problems := LayerCheck.new().check(files, _layers, {"App": "scenes/app/app.gd"})
	assert_eq(problems.size(), 1)
	assert_string_starts_with(problems[0], "scripts/board/a.gd:3 uses scenes/app/app.gd")


func test_a_script_in_no_listed_folder_is_named() -> void:
	var problems := LayerCheck.new().check({"stray/a.gd": "extends Node\n"}, _layers, {})
	assert_eq(
		Array(problems),
		["stray/a.gd is in no layer: add its folder to docs/architecture.md's list"]
	)


# Every .gd under res://`folder`, as {path relative to res://: text}.
func _read_scripts(folder: String, files: Dictionary) -> void:
	if folder in SKIPPED:
		return
	var dir := DirAccess.open("res://" + folder)
	if dir == null:
		return
	for file in dir.get_files():
		if file.ends_with(".gd"):
			files[folder + "/" + file] = FileAccess.get_file_as_string(
				"res://%s/%s" % [folder, file]
			)
	for sub in dir.get_directories():
		if not sub.begins_with("."):
			_read_scripts(folder + "/" + sub, files)


func _autoloads() -> Dictionary:
	var found := {}
	for property in ProjectSettings.get_property_list():
		var key: String = property.name
		if key.begins_with("autoload/"):
			var path: String = ProjectSettings.get_setting(key)
			found[key.trim_prefix("autoload/")] = path.trim_prefix("*").trim_prefix("res://")
	return found
