@tool
extends RefCounted
## The controls both play-analysis sections of the dock share, added to a section in this
## order: the "Play analysis" title; Analyze, Cancel (off until a run starts) and Show (on)
## in a row; a progress bar (hidden until a run starts); a status line that wraps.

var analyze: Button
var cancel: Button
var show: CheckBox
var progress: ProgressBar
var status: Label


## Builds the controls into `section`; `analyze_tip` says what Analyze does. Analyze calls
## `on_analyze`, Cancel `on_cancel`, and Show passes its new state to `on_show`.
func _init(
	section: VBoxContainer,
	analyze_tip: String,
	on_analyze: Callable,
	on_cancel: Callable,
	on_show: Callable
) -> void:
	var title := Label.new()
	title.text = "Play analysis"
	section.add_child(title)
	var row := HBoxContainer.new()
	analyze = Button.new()
	analyze.text = "Analyze"
	analyze.tooltip_text = analyze_tip
	row.add_child(analyze)
	cancel = Button.new()
	cancel.text = "Cancel"
	cancel.disabled = true
	row.add_child(cancel)
	show = CheckBox.new()
	show.text = "Show"
	show.button_pressed = true
	row.add_child(show)
	section.add_child(row)
	progress = ProgressBar.new()
	progress.max_value = 1.0
	progress.step = 0.0  # a bar that moves with the first climbs, not in whole percents
	progress.show_percentage = false  # the status line says how far, to a tenth early on
	progress.visible = false
	section.add_child(progress)
	status = Label.new()
	status.autowrap_mode = TextServer.AUTOWRAP_WORD_SMART
	section.add_child(status)
	analyze.pressed.connect(on_analyze)
	cancel.pressed.connect(on_cancel)
	show.toggled.connect(on_show)


## A run has started: Analyze off, Cancel on, an empty progress bar, `text` as the status.
func show_running(text: String) -> void:
	analyze.disabled = true
	cancel.disabled = false
	progress.visible = true
	progress.value = 0.0
	status.text = text


## The run is over: Analyze on, Cancel off, the progress bar hidden.
func show_idle() -> void:
	analyze.disabled = false
	cancel.disabled = true
	progress.visible = false
