extends GutTest
## "New board…": one step writes a board file and a level scene whose root BoardNode shows
## it, both loadable at once; a taken or bad name writes nothing.

const NewBoardFiles := preload("res://addons/board_editor/core/new_board_files.gd")

const DIR := "user://test_new_board_files"


func before_each() -> void:
	DirAccess.make_dir_recursive_absolute(DIR)


func after_each() -> void:
	for file in DirAccess.get_files_at(DIR):
		DirAccess.remove_absolute(DIR.path_join(file))
	DirAccess.remove_absolute(DIR)


func test_creates_a_board_file_and_a_scene_with_a_board_node() -> void:
	for kind: int in [BoardLevel.Kind.PACHINKO, BoardLevel.Kind.MAZE]:
		var board_path := DIR.path_join("try_%d.board" % kind)
		var made := NewBoardFiles.create(kind, "try", "Try Out", DIR, board_path)
		assert_false(made.has("error"), str(made.get("error", "")))
		if made.has("error"):
			continue
		var scene := load(made["scene"]) as PackedScene
		assert_not_null(scene, "the scene loads")
		var root := scene.instantiate()
		assert_true(root is BoardNode, "its root is a BoardNode")
		if root is BoardNode:
			var level := (root as BoardNode).level
			assert_eq(level.resource_path, board_path, "showing the board's own file")
			assert_eq(level.kind, kind)
			assert_eq(level.display_name, "Try Out")
			assert_eq(level.board_id, "%s_try" % BoardLevel.kind_name(kind))
			assert_eq(BoardValidator.errors(level).size(), 0, "a new board has no errors")
		root.free()
		DirAccess.remove_absolute(made["scene"])


func test_a_taken_or_bad_name_is_refused_by_name() -> void:
	var kind := BoardLevel.Kind.PACHINKO
	assert_string_contains(NewBoardFiles.problem(kind, "classic"), "classic.board already exists")
	assert_string_contains(NewBoardFiles.problem(kind, "Bad Name"), "Use only a-z, 0-9 and _")
	var made := NewBoardFiles.create(kind, "classic", "Classic again")
	assert_string_contains(str(made.get("error", "")), "Not created: classic.board already exists")
	var scene := NewBoardFiles.scene_path_for(kind, "try", DIR)
	FileAccess.open(scene, FileAccess.WRITE).store_string("taken")
	assert_eq(NewBoardFiles.problem(kind, "zz_new", DIR), "", "a free name is fine")
	var taken := NewBoardFiles.problem(kind, "try", DIR)
	assert_eq(taken, "pachinko_try.tscn already exists; pick another name.")
