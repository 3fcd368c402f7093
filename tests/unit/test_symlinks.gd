extends GutTest
## Symbolic links planted in the player's folder: an import into a My boards folder that is
## a link is refused with the link named, and no save (board import, settings, replay) ever
## writes through a link planted where an old build put its temporary file.

const ROOT := "user://test_symlinks"
const OUTSIDE := "user://test_symlinks_outside"
const GOOD := "res://levels/pachinko/classic.board"
const VICTIM_TEXT := "a file outside the game's folders\n"


func before_each() -> void:
	_remove_tree(ROOT)
	_remove_tree(OUTSIDE)
	DirAccess.make_dir_recursive_absolute(ROOT)
	DirAccess.make_dir_recursive_absolute(OUTSIDE)


func after_all() -> void:
	_remove_tree(ROOT)
	_remove_tree(OUTSIDE)


func _link(target: String, link: String) -> void:
	var dir := DirAccess.open("user://")
	var made := dir.create_link(
		ProjectSettings.globalize_path(target), ProjectSettings.globalize_path(link)
	)
	assert_eq(made, OK, "the test could plant the link %s" % link)


func _victim() -> String:
	var victim := OUTSIDE + "/victim.txt"
	var file := FileAccess.open(victim, FileAccess.WRITE)
	file.store_string(VICTIM_TEXT)
	file.close()
	return victim


func test_a_linked_boards_folder_is_refused_by_name() -> void:
	_link(OUTSIDE, ROOT + "/pachinko")
	var outcome := UserBoards.import_file(ProjectSettings.globalize_path(GOOD), ROOT)
	assert_eq(
		outcome.get("error"),
		(
			"classic.board: %s/pachinko is a symbolic link; boards are only written to real folders"
			% ROOT
		)
	)
	assert_eq(DirAccess.get_files_at(OUTSIDE).size(), 0, "nothing was written outside")


func test_an_import_never_writes_through_a_planted_temporary_link() -> void:
	DirAccess.make_dir_recursive_absolute(ROOT + "/pachinko")
	var victim := _victim()
	_link(victim, ROOT + "/pachinko/.classic.board.partial")
	var outcome := UserBoards.import_file(ProjectSettings.globalize_path(GOOD), ROOT)
	assert_true(outcome.has("path"), str(outcome.get("error", "")))
	assert_eq(FileAccess.get_file_as_string(victim), VICTIM_TEXT, "the linked file is untouched")
	var written := ROOT + "/pachinko/classic.board"
	assert_eq(FileAccess.get_file_as_bytes(written), FileAccess.get_file_as_bytes(GOOD))


func test_settings_never_write_through_a_planted_temporary_link() -> void:
	var victim := _victim()
	var settings := ROOT + "/settings.cfg"
	_link(victim, settings + ".tmp")
	assert_eq(IniText.write_file(settings, "[meta]\nversion=1\n"), OK)
	assert_eq(FileAccess.get_file_as_string(victim), VICTIM_TEXT, "the linked file is untouched")
	assert_eq(FileAccess.get_file_as_string(settings), "[meta]\nversion=1\n")


func test_nothing_is_written_into_a_linked_folder() -> void:
	_link(OUTSIDE, ROOT + "/replays")
	assert_eq(SafeWrite.link_on_path(ROOT + "/replays/x.replay"), ROOT + "/replays")
	assert_eq(SafeWrite.write_text(ROOT + "/replays/x.replay", "x"), ERR_FILE_CANT_WRITE)
	assert_eq(DirAccess.get_files_at(OUTSIDE).size(), 0)


func test_no_temporary_file_is_left_behind() -> void:
	assert_eq(SafeWrite.write_text(ROOT + "/a.txt", "one"), OK)
	assert_eq(SafeWrite.write_text(ROOT + "/a.txt", "two"), OK)
	assert_eq(Array(DirAccess.get_files_at(ROOT)), ["a.txt"])
	assert_eq(FileAccess.get_file_as_string(ROOT + "/a.txt"), "two")


# Removes a scratch folder, hidden files and links included (a link itself, never what it
# points at).
static func _remove_tree(path: String) -> void:
	var parent := DirAccess.open(path.get_base_dir())
	if parent != null and parent.is_link(path):
		DirAccess.remove_absolute(path)
		return
	var dir := DirAccess.open(path)
	if dir == null:
		return
	dir.include_hidden = true
	for name in dir.get_files():
		DirAccess.remove_absolute(path.path_join(name))
	for folder in dir.get_directories():
		_remove_tree(path.path_join(folder))
	DirAccess.remove_absolute(path)
