class_name TiltPacking
extends RefCounted
## Packs the frames of a `"tilts"` record into one short text: the form a replay file gives
## to frames whose tilt changes every frame (a pilot or a player steering), where a line per
## frame would make a minute of play a large file.
##
## In memory the frames are whole numbers, three per frame: steps, tilt x, tilt y (hundredths
## of a degree). In the file the first frame's tilt is written as it is and each later tilt
## as its change from the frame before, since a steering hand changes the tilt by a little
## each frame. Every number is zig-zag folded to >= 0 (0, -1, 1, -2 ... → 0, 1, 2, 3 ...) and
## written as digits of the URL-safe base64 alphabet, five bits of value a digit, low bits
## first; a digit of 32 or more says another digit follows. Small changes take one
## character, a change across the whole tilt range three.
##
## Decoding is plain arithmetic on the characters: no engine parser, no code, every number
## bounded by MAX_DIGITS before it is used.

## The 64 digits, values 0 to 63 in order (URL-safe base64; nothing JSON must escape).
const DIGITS := "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_"
## Digits one number may take: 4 × 5 bits holds any steps or tilt change a replay allows.
const MAX_DIGITS := 4
## Whole numbers per frame: steps, x, y.
const PER_FRAME := 3
const _MORE := 32
const _VALUE_BITS := 5


## The text for `numbers` (steps, x, y per frame, x and y absolute).
static func encode(numbers: Array) -> String:
	var parts := PackedStringArray()
	for index in numbers.size():
		var value: int = numbers[index]
		if index >= PER_FRAME and index % PER_FRAME != 0:
			var before: int = numbers[index - PER_FRAME]
			value -= before
		parts.append(_number_text(_fold(value)))
	return "".join(parts)


## {"numbers": Array} (steps, x, y per frame, x and y absolute again) or {"error": ...}.
## Checks the characters and the framing only; the caller checks the ranges.
static func decode(text: String) -> Dictionary:
	var numbers: Array[int] = []
	var value := 0
	var digits := 0
	for character in text:
		var digit := DIGITS.find(character)
		if digit < 0:
			return {
				"error": 'the packed frames hold "%s", not a base64 digit' % character.c_escape()
			}
		value |= (digit % _MORE) << (_VALUE_BITS * digits)
		digits += 1
		if digit >= _MORE:
			if digits >= MAX_DIGITS:
				return {"error": "a packed number runs past %d digits" % MAX_DIGITS}
			continue
		numbers.append(_unfold(value))
		value = 0
		digits = 0
	if digits > 0:
		return {"error": "the packed frames end in the middle of a number"}
	if numbers.is_empty() or numbers.size() % PER_FRAME != 0:
		return {"error": "the packed frames must hold steps, x and y for each frame"}
	for index in range(PER_FRAME, numbers.size()):
		if index % PER_FRAME != 0:
			numbers[index] += numbers[index - PER_FRAME]
	return {"numbers": numbers}


static func _number_text(folded: int) -> String:
	var text := ""
	while folded >= _MORE:
		text += DIGITS[_MORE + (folded % _MORE)]
		folded >>= _VALUE_BITS
	return text + DIGITS[folded]


# 0, -1, 1, -2, 2 ... → 0, 1, 2, 3, 4 ...
static func _fold(value: int) -> int:
	return value * 2 if value >= 0 else -value * 2 - 1


static func _unfold(folded: int) -> int:
	return folded >> 1 if folded % 2 == 0 else -((folded + 1) >> 1)
