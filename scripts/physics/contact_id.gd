class_name ContactId
extends RefCounted
## Which static shape a ball touches, as one int: the shape's kind in the low KIND_BITS and
## its index above them. Ball slots remember the (up to two) shapes they touched last step
## by this id, so a contact that persists slides instead of bouncing again. Internal to
## scripts/physics. The id of pin k is (k << KIND_BITS) | KIND_PIN, of wall k
## (k << KIND_BITS) | KIND_WALL, of blade b of windmill m ((m << BLADE_BITS | b) << KIND_BITS)
## | KIND_BLADE; the narrow phase builds them inline, once per contact.

## Bits that hold the kind.
const KIND_BITS := 3
## No contact (kind 0, index 0): a fresh ball slot holds this.
const NONE := 0
const KIND_RING := 1
const KIND_PIN := 2
const KIND_WALL := 3
const KIND_BLADE := 4
## Bits that hold a blade's number within its windmill.
const BLADE_BITS := 6
## The ring border: there is only one.
const RING := KIND_RING
