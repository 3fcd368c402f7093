@tool
extends RefCounted
## One row of a dock panel's numbers: a label that takes the spare width and a SpinBox.
## The arrows move by the spec's step, but a value is kept to the board file's precision
## (0.01), so a field shows 373.33 where the board has 373.33, not 373.5.

## What a typed or shown value is rounded to (BoardTextWriter.PRECISION).
const PRECISION := 0.01


## A row for `spec` ([label, lowest, highest, arrow step, whole]); `whole` (optional, true)
## keeps whole numbers (counts, payouts). Its SpinBox is `spin_of(row)`.
static func make(spec: Array) -> HBoxContainer:
	var row := HBoxContainer.new()
	var label := Label.new()
	label.text = spec[0]
	label.size_flags_horizontal = Control.SIZE_EXPAND_FILL
	label.autowrap_mode = TextServer.AUTOWRAP_WORD_SMART  # never wider than the dock
	row.add_child(label)
	var spin := SpinBox.new()
	spin.min_value = spec[1]
	spin.max_value = spec[2]
	var arrow_step: float = spec[3]
	var whole: bool = spec.size() > 4 and spec[4]
	spin.step = arrow_step if whole else PRECISION
	spin.custom_arrow_step = arrow_step
	spin.custom_minimum_size = Vector2(96, 0)
	row.add_child(spin)
	return row


## The SpinBox of a row made by make().
static func spin_of(row: HBoxContainer) -> SpinBox:
	return row.get_child(1) as SpinBox
