@tool
extends Node
## A hook for trying the board tool by hand or with xdotool under Xvfb
## (tools/editor_try.sh): opens BOARD_EDITOR_OPEN="<scene.tscn>", selects its BoardNode so
## the board tool shows, and leaves the editor running.

const ENV := "BOARD_EDITOR_OPEN"


func _init(_plugin: EditorPlugin) -> void:
	pass


func _ready() -> void:
	_open.call_deferred()


func _open() -> void:
	for i in 30:
		await get_tree().process_frame
	EditorInterface.open_scene_from_path(OS.get_environment(ENV))
	for i in 10:
		await get_tree().process_frame
	var root := EditorInterface.get_edited_scene_root()
	if root == null:
		push_error("open_board: %s did not open." % OS.get_environment(ENV))
		return
	EditorInterface.get_selection().clear()
	EditorInterface.get_selection().add_node(root)
	EditorInterface.edit_node(root)
	EditorInterface.set_main_screen_editor("2D")
	print("open_board: ready")
