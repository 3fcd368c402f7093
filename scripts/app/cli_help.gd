class_name CliHelp
extends RefCounted
## The `--help` text, written from the flag table so it always lists every flag.

## Help's left column width: the widest flag as written, plus a gap.
const COLUMN := 20
## Width of the description column, so help lines fit in 100 characters.
const TEXT_WIDTH := 70


## Every flag with what it does and an example, then the exit codes.
static func text() -> String:
	var lines := PackedStringArray(
		[
			"Board Studio. With no flags the game starts as usual. Flags go after `--`:",
			"  godot --headless --path . -- FLAGS",
			"",
			"Commands (one at a time):",
		]
	)
	lines.append_array(_rows(true))
	lines.append("")
	lines.append("Options (with the command they name):")
	lines.append_array(_rows(false))
	lines.append("")
	lines.append("Exit codes: %d done;" % CliFlags.EXIT_OK)
	lines.append(
		"  1 a board refused (--check-boards) or a replay that ended elsewhere (--replay);"
	)
	lines.append(
		(
			"  %d unknown flag, bad value, or a board or replay that cannot be read."
			% CliFlags.EXIT_USAGE
		)
	)
	return "\n".join(lines)


static func _rows(commands: bool) -> PackedStringArray:
	var lines := PackedStringArray()
	for row: Dictionary in CliFlags.FLAGS:
		var is_command: bool = row.get("command", false)
		if is_command != commands:
			continue
		var help := str(row["help"])
		if row.has("choices"):
			var choices: Array = row["choices"]
			help += " %s: %s." % [row["placeholder"], "|".join(PackedStringArray(choices))]
		if row.has("for"):
			var owners: Array = row["for"]
			help += " With %s." % " or ".join(PackedStringArray(owners))
		var left := CliFlags.usage_of(row)
		for line: String in _wrap(help):
			lines.append("  %s%s" % [left.rpad(COLUMN), line])
			left = ""
		lines.append("  %se.g. -- %s" % ["".rpad(COLUMN), row["example"]])
	return lines


# `help_text` cut at spaces into lines of at most TEXT_WIDTH characters.
static func _wrap(help_text: String) -> PackedStringArray:
	var lines := PackedStringArray()
	var line := ""
	for word: String in help_text.split(" ", false):
		if not line.is_empty() and line.length() + 1 + word.length() > TEXT_WIDTH:
			lines.append(line)
			line = ""
		line = word if line.is_empty() else "%s %s" % [line, word]
	lines.append(line)
	return lines
