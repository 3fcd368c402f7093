extends SceneTree
## One scripted quit while the level select is still loading board files (issue 25, item 3):
## fills a scratch My boards folder with BOARDS copies of a board (once), opens the level
## select on it, waits the number of frames given after `--` (default 2) and quits at once.
## With "drop" after the frames, a board file is dropped on the window first (an import runs
## when the quit comes). tools/quit_check.sh runs it many times; a crash shows as a bad exit
## status or a crash line in the log.
##   tools/godot.sh --headless --path . -s res://tools/quit_during_loading.gd -- 3 drop

const LEVEL_SELECT := "res://scenes/menu/level_select.tscn"
const ROOT := "user://quit_check_boards"
const SOURCE := "res://levels/pachinko/tulips.board"
const BOARDS := 120


func _initialize() -> void:
	_fill_folder()
	var args := OS.get_cmdline_user_args()
	var frames := int(args[0]) if not args.is_empty() and args[0].is_valid_int() else 2
	var screen := (load(LEVEL_SELECT) as PackedScene).instantiate()
	screen.set("user_root", ROOT)
	root.add_child(screen)
	current_scene = screen
	if args.has("drop"):
		await process_frame
		var dropped := ProjectSettings.globalize_path("res://levels/maze/the_deep.board")
		root.files_dropped.emit(PackedStringArray([dropped, dropped]))
	for frame in frames:
		await process_frame
	print("quitting after %d frames, loading: %s" % [frames, screen.call("is_loading")])
	quit(0)


func _fill_folder() -> void:
	var folder := ROOT + "/pachinko"
	DirAccess.make_dir_recursive_absolute(folder)
	if DirAccess.get_files_at(folder).size() >= BOARDS:
		return
	var bytes := FileAccess.get_file_as_bytes(SOURCE)
	for index in BOARDS:
		var file := FileAccess.open("%s/board_%03d.board" % [folder, index], FileAccess.WRITE)
		file.store_buffer(bytes)
		file.close()
