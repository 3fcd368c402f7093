class_name BoardFileName
extends RefCounted
## Plain file names for the player's boards: the stem an imported file is saved under is
## also the id a board loaded from user:// gets, so both UserBoards (which writes the file)
## and BoardLoader (which names the board) ask here.

## The longest file name (without ".board") an imported board gets.
const MAX_STEM := 48


## A file name stem made only of a-z, 0-9, "_" and "-" (never empty), used for imported files
## and for the ids of the player's boards, so no name can reach a save file's syntax.
static func safe_stem(text: String) -> String:
	var stem := ""
	for character in text.to_lower():
		var code := character.unicode_at(0)
		var plain := (code >= 97 and code <= 122) or (code >= 48 and code <= 57)
		stem += character if plain or character == "-" else "_"
	stem = stem.lstrip("_-").left(MAX_STEM)
	return stem if not stem.is_empty() else "board"
