@tool
extends RefCounted
## The pins a pocket stamps (PocketStamp's rim and special pin) in the shape the editor's
## actions append: {pins, special} with one special flag per pin.


## The stamped pins of `spec` on `level`: rim pins, then the special pin (flag 1).
static func stamp(level: BoardLevel, spec: PocketSpec) -> Dictionary:
	var pins := PocketStamp.rim_pins(spec, level.pin_radius, level.ball_radius)
	var special := PackedByteArray()
	special.resize(pins.size())
	if not pins.is_empty():
		special[pins.size() - 1] = 1
	return {"pins": pins, "special": special}
