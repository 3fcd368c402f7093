extends RefCounted
## The command line the band tools share (tools/tulip_band.gd, tools/attacker_band.gd):
## --board=ID, --powers=a,b,..., --seeds=a,b,... and --shots=N, each with the tool's own
## default, and the board they name loaded.

## The board's id (levels/pachinko/<board>.board).
var board := ""
## The handle strengths to measure, in order.
var powers: Array[int] = []
## The seeds each strength is played with.
var seeds: Array[int] = [1]
## Shots per strength and seed (tools that count shots).
var shots := 0


## Reads `args` (OS.get_cmdline_user_args()) over the defaults given.
func read(
	args: PackedStringArray, default_board: String, default_powers: Array[int], default_shots := 0
) -> void:
	board = default_board
	shots = default_shots
	powers.clear()
	for arg in args:
		var value := arg.get_slice("=", 1)
		if arg.begins_with("--board="):
			board = value
		elif arg.begins_with("--powers="):
			powers = _ints(value)
		elif arg.begins_with("--shots="):
			shots = int(value)
		elif arg.begins_with("--seeds="):
			seeds = _ints(value)
	if powers.is_empty():
		powers = default_powers.duplicate()


## The named board, or null after printing why (`tool` names the tool in the message).
func load_level(tool: String) -> BoardLevel:
	var result := BoardLoader.load_board("res://levels/pachinko/%s.board" % board)
	if not result.ok():
		printerr("%s: cannot load board '%s'" % [tool, board])
		return null
	return result.level


static func _ints(text: String) -> Array[int]:
	var out: Array[int] = []
	for part in text.split(",", false):
		out.append(int(part))
	return out
