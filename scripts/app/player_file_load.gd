class_name PlayerFileLoad
extends RefCounted
## Loads one of the player's versioned INI files (settings, best results) by one rule: no file
## is no problem; a file that is no usable text is moved aside (kept for the player); one from
## a newer version is left as it is and never written over; a usable one hands its sections
## to the owner, and a file with entries the owner could not use is moved aside too.

## "" when all was well, else a sentence for the player naming the problem and where the old
## file went.
var message := ""
## True when the file must not be written over this run (from a newer version, or damaged and
## not moved aside).
var untouchable := false


## Loads `path`, written by format `version` at the newest. `take(sections, file_version)`
## uses what it can and returns the entries it could not use. `words` holds three sentences,
## each formatted with the file name and then: for "damaged" why, for "newer" the file's
## version (a whole number), for "partly" the entries left out.
static func run(path: String, version: int, take: Callable, words: Dictionary) -> PlayerFileLoad:
	var loaded := PlayerFileLoad.new()
	var read := IniText.read_versioned_file(path)
	if read.has("missing"):
		return loaded
	if read.has("error"):
		var damaged: String = words["damaged"] % [path.get_file(), read["error"]]
		loaded._set_aside(path, damaged)
		return loaded
	var file_version: int = read["version"]
	if file_version > version:
		loaded.untouchable = true
		loaded.message = words["newer"] % [path.get_file(), file_version]
		return loaded
	var problems: PackedStringArray = take.call(read["sections"], file_version)
	var unreadable_lines: PackedStringArray = read["problems"]
	problems.append_array(unreadable_lines)
	if not problems.is_empty():
		var partly: String = words["partly"] % [path.get_file(), ", ".join(problems)]
		loaded._set_aside(path, partly)
	return loaded


func _set_aside(path: String, sentence: String) -> void:
	var kept := UserFile.keep_aside(path)
	untouchable = kept.is_empty()
	message = "%s %s" % [sentence, UserFile.kept_note(kept)]
