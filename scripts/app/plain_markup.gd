class_name PlainMarkup
extends RefCounted
## Makes text safe to put into a BBCode label. Text that came from a file (a board's name or
## description, a field name or path quoted in an error) must never be parsed as markup:
## `[img]` and `[font]` load resources, and a resource can carry a script.


## `text` with every "[" written as the [lb] tag, so a BBCode label shows it as typed and
## no tag in it takes effect.
static func escape(text: String) -> String:
	return text.replace("[", "[lb]")
