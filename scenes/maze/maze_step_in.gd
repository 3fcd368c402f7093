class_name MazeStepIn
extends Node
## Brings a maze stage's parts onto the screen one drawn frame after another (walls, frame,
## balls, floor, table), then emits `shown_in_full`. On software GL each part's shaders
## compile the first time it is drawn, which held the main thread 2 to 4 s in one frame with
## the loading curtain's ring standing still (tools/maze_open_time.sh, a cold shader cache):
## one part a frame keeps the ring turning between them (longest stall 0.7 to 1.3 s).

## Every part has been drawn once.
signal shown_in_full

var _stage: MazeStage
# parts still to bring on, and the frames left before the last has been drawn
var _waiting: Array[Node3D] = []
var _steps_left := 0


func _init() -> void:
	set_process(false)


## Hides `stage`'s shown parts now and brings them on, one each frame, from the next.
func start(stage: MazeStage) -> void:
	_stage = stage
	_waiting.clear()
	var board := stage.board()
	for part: Node3D in [
		board.part("walls"), board.part("frame"), stage.balls(), board.part("floor"), stage.table()
	]:
		if part.visible:
			part.hide()
			_waiting.append(part)
	# each frame draws what the one before it brought on: one frame more for the last part
	_steps_left = _waiting.size() + 1
	set_process(true)


func _process(_delta: float) -> void:
	_steps_left -= 1
	if _waiting.is_empty() or _steps_left <= 0:
		_waiting.clear()
		set_process(false)
		shown_in_full.emit()
		return
	var part: Node3D = _waiting.pop_front()
	# the table follows the Low setting, which may have changed meanwhile
	part.visible = part != _stage.table() or not _stage.low_graphics
