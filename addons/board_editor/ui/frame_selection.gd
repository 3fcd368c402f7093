@tool
extends RefCounted
## Godot's "Frame Selection" (Shift+F, and View ▸ Frame Selection / Center Selection) for
## the board tool: Godot frames only nodes, and the BoardNode tells it no size (a script
## cannot), so it centred the view on the node's origin, (0, 0). While the tool is open the
## key frames the selected items instead (the whole board when none is selected), and after
## the View menu's items the tool frames them again once Godot has moved the view.

const EditCommands := preload("res://addons/board_editor/core/edit_commands.gd")
const BoardInput := preload("res://addons/board_editor/board_input.gd")
## Board pixels kept round the framed items, so a lone pin is not framed edge to edge.
const MARGIN := 40.0
## The View menu items (as Godot names them) that frame or centre the selection.
const MENU_ITEMS: Array[String] = ["Frame Selection", "Center Selection"]


## The board area to frame: the selected items' extent grown by MARGIN, or the whole board
## (with everything placed off it) when nothing is selected.
static func area(level: BoardLevel, selection: Array[Vector2i]) -> Rect2:
	if level == null:
		return Rect2()
	if selection.is_empty():
		return BoardInput.edit_area(level).grow(MARGIN)
	var bounds := EditCommands.extent_of(level, selection[0])
	for k in range(1, selection.size()):
		bounds = bounds.merge(EditCommands.extent_of(level, selection[k]))
	return bounds.grow(MARGIN)


## True for Godot's Frame Selection key, Shift+F, pressed.
static func is_frame_key(event: InputEvent) -> bool:
	var key := event as InputEventKey
	if key == null or not key.pressed or key.echo or key.keycode != KEY_F:
		return false
	return key.shift_pressed and not key.is_command_or_control_pressed() and not key.alt_pressed


## Calls `on_framed` after Godot's own View ▸ Frame Selection or Center Selection (its popup
## menu in the 2D editor); does nothing where the menu cannot be found. Call it once.
static func follow_view_menu(on_framed: Callable) -> void:
	var main := EditorInterface.get_editor_main_screen()
	var editors := main.find_children("*", "CanvasItemEditor", true, false)
	if editors.is_empty():
		return
	for button: Node in editors[0].find_children("*", "MenuButton", true, false):
		var popup := (button as MenuButton).get_popup()
		for i in popup.item_count:
			if popup.get_item_text(i) in MENU_ITEMS:
				popup.id_pressed.connect(func(id: int) -> void: _after_item(popup, id, on_framed))
				break


static func _after_item(popup: PopupMenu, id: int, on_framed: Callable) -> void:
	var index := popup.get_item_index(id)
	if index >= 0 and popup.get_item_text(index) in MENU_ITEMS:
		# Godot centres its view a frame later (call_deferred): move it after that.
		popup.get_tree().create_timer(0.05).timeout.connect(on_framed)
