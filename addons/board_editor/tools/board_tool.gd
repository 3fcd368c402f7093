@tool
extends RefCounted
## Base of the editor's tools. A tool turns mouse input (already in board pixels) into
## actions committed through the session, and draws its preview over the viewport.

const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const OverlayDraw := preload("res://addons/board_editor/ui/overlay_draw.gd")
const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const HitTest := preload("res://addons/board_editor/core/hit_test.gd")

## How close (screen px) the mouse must be to pick something.
const PICK_PIXELS := 8.0

## The editor state this tool works on.
var session: BoardEditSession
## The mouse position in board pixels (for previews).
var hover := Vector2.ZERO
## Board pixels per screen pixel, set by the plugin from the view zoom.
var pixel := 1.0


func _init(on_session: BoardEditSession) -> void:
	session = on_session


## Left button pressed at `at`; true when the tool used the event.
func press(_at: Vector2, _event: InputEventMouseButton) -> bool:
	return false


## Mouse moved; true when the tool used the event.
func motion(at: Vector2, _event: InputEventMouseMotion) -> bool:
	hover = at
	return false


## Left button released; true when the tool used the event.
func release(_at: Vector2, _event: InputEventMouseButton) -> bool:
	return false


## Abandons a drag in progress, restoring the board; true if there was one.
func cancel() -> bool:
	return false


## Draws the tool's preview. `to_screen` maps board pixels to the overlay.
func draw(_canvas: Control, _to_screen: Transform2D) -> void:
	pass


## The session's board.
func level() -> BoardLevel:
	return session.level


## The item under `at` that the tool may touch (nothing on a hidden or locked layer).
func pick(at: Vector2) -> Vector2i:
	var item := HitTest.pick(level(), at, tolerance())
	return item if item == BoardItems.NONE or session.can_pick(item) else BoardItems.NONE


## Pick tolerance in board pixels.
func tolerance() -> float:
	return PICK_PIXELS * pixel
