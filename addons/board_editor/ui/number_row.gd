@tool
extends RefCounted
## One row of a dock panel's numbers: a label that takes the spare width and a SpinBox.


## A row for `spec` ([label, lowest, highest, step]); its SpinBox is `spin_of(row)`.
static func make(spec: Array) -> HBoxContainer:
	var row := HBoxContainer.new()
	var label := Label.new()
	label.text = spec[0]
	label.size_flags_horizontal = Control.SIZE_EXPAND_FILL
	row.add_child(label)
	var spin := SpinBox.new()
	spin.min_value = spec[1]
	spin.max_value = spec[2]
	spin.step = spec[3]
	spin.custom_minimum_size = Vector2(96, 0)
	row.add_child(spin)
	return row


## The SpinBox of a row made by make().
static func spin_of(row: HBoxContainer) -> SpinBox:
	return row.get_child(1) as SpinBox
