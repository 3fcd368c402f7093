extends GutTest
## A board file's uid: ResourceSaver.set_uid on a `.board` writes its `<file>.uid` beside
## it (tools/make_original_boards.gd gives every new board one), instead of failing with
## "File unrecognized".

const FOLDER := "user://test_board_uid"


func after_each() -> void:
	for name in DirAccess.get_files_at(FOLDER):
		DirAccess.remove_absolute(FOLDER.path_join(name))
	DirAccess.remove_absolute(FOLDER)


func test_set_uid_writes_the_uid_file_of_a_new_board() -> void:
	DirAccess.make_dir_recursive_absolute(FOLDER)
	var path := FOLDER.path_join("fresh.board")
	var level := (load("res://levels/pachinko/classic.board") as BoardLevel).duplicate_level()
	assert_eq(ResourceSaver.save(level, path), OK)
	var uid := ResourceUID.create_id()
	assert_eq(ResourceSaver.set_uid(path, uid), OK)
	var text := FileAccess.get_file_as_string(path + ".uid")
	assert_eq(text, ResourceUID.id_to_text(uid) + "\n", "Godot's own .uid file format")
	assert_eq(ResourceSaver.set_uid(path, uid), OK, "setting the same uid again is fine")
	assert_eq(ResourceSaver.set_uid(path, ResourceUID.INVALID_ID), ERR_INVALID_PARAMETER)
