extends RefCounted
## Which static shape a ball touches, as one int: the shape's kind in the low KIND_BITS and
## its index above them. Ball slots remember the (up to two) shapes they touched last step
## by this id, so a contact that persists slides instead of bouncing again. Internal to
## scripts/physics; the hot loops build ids inline with the same shift and kind constants.

## Bits that hold the kind.
const KIND_BITS := 2
## No contact (kind 0, index 0): a fresh ball slot holds this.
const NONE := 0
const KIND_RING := 1
const KIND_PIN := 2
const KIND_WALL := 3
## The ring border: there is only one.
const RING := KIND_RING


## The id of pin `index`.
static func pin(index: int) -> int:
	return (index << KIND_BITS) | KIND_PIN


## The id of capsule wall `index`.
static func wall(index: int) -> int:
	return (index << KIND_BITS) | KIND_WALL


## The kind of `id` (NONE, KIND_RING, KIND_PIN or KIND_WALL).
static func kind_of(id: int) -> int:
	return id & ((1 << KIND_BITS) - 1)


## The shape index of `id` (0 for the ring and for NONE).
static func index_of(id: int) -> int:
	return id >> KIND_BITS
