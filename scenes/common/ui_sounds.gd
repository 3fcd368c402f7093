class_name UiSounds
extends Node
## Menu sounds: a click when any button under this node's parent is pressed, and a short
## tick while a slider moves (so the volume sliders preview the level they set). Buttons
## added later (the binding list, the settings screen over a menu) are picked up too.
## Runs while the tree is paused, for the pause menu.

const SLIDER_TICK_INTERVAL_MS := 90

var _bank: SoundBank
var _last_tick_ms := -1000


func _ready() -> void:
	process_mode = Node.PROCESS_MODE_ALWAYS
	_bank = SoundBank.new()
	_bank.voices = 4
	add_child(_bank)
	var watched := get_parent()
	for node in watched.find_children("*", "Control", true, false):
		_watch(node)
	get_tree().node_added.connect(_on_node_added)


func _on_node_added(node: Node) -> void:
	if node is Control and get_parent() != null and get_parent().is_ancestor_of(node):
		_watch(node)


func _watch(node: Node) -> void:
	if node is BaseButton:
		(node as BaseButton).pressed.connect(_click)
	elif node is Slider:
		(node as Slider).value_changed.connect(_tick)


## A dull knock for a press the screen refuses (Enter on a locked board). Returns whether
## it played.
func refuse() -> bool:
	return is_inside_tree() and _bank.play(SoundBank.WALL_THUD, -4.0, 0.8)


## How many sounds it has played (the bank's count, for tests).
func played_count() -> int:
	return _bank.played_count() if _bank != null else 0


func _click() -> void:
	if is_inside_tree():  # a button that changed the scene has already taken us out
		_bank.play(SoundBank.UI_CLICK, -6.0)


func _tick(_value: float) -> void:
	var now := Time.get_ticks_msec()
	if is_inside_tree() and now - _last_tick_ms >= SLIDER_TICK_INTERVAL_MS:
		_last_tick_ms = now
		# the slider's new volume is already on the bus, so this click previews it
		_bank.play(SoundBank.UI_CLICK, -10.0, 1.4)
