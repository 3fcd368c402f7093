class_name FasciaNames
extends RefCounted
## The machines a pachinko board may be dressed as: the fascia (the art behind the pins), its
## palette and its name plate, picked by a board file's optional `"fascia"` line
## (`{"fascia": "sakura"}`; a file without one is the classic machine). Only the name lives
## with the board; the pictures are the view's (scenes/board_view/fascia/).

## The chapter's machine: the moon face and the water dragon. Boards without a fascia wear it.
const CLASSIC := "classic"
## Every machine, in the order the editor lists them.
const NAMES: Array[String] = [CLASSIC, "country", "garden", "neon", "sakura"]
## What the editor calls each machine (NAMES order).
const TITLES: Array[String] = [
	"Classic: moon and dragon",
	"Country: windmill in the fields",
	"Garden: tulip beds",
	"Neon: fever lights",
	"Sakura: blossom at night",
]


## True when `name` is one of NAMES.
static func is_known(name: Variant) -> bool:
	return name is String and NAMES.has(name)


## The editor's name for machine `name` ("Garden: tulip beds"); the name itself when unknown.
static func title_of(name: String) -> String:
	var index := NAMES.find(name)
	return TITLES[index] if index >= 0 else name


## The machines for a message: "classic", "country", "garden", "neon" or "sakura".
static func choices() -> String:
	var quoted := NAMES.map(func(name: String) -> String: return '"%s"' % name)
	return ", ".join(quoted.slice(0, -1)) + " or " + str(quoted[-1])
