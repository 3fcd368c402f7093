class_name ReplayWriter
extends RefCounted
## Writes a Replay as JSON Lines: one header object, then one record (a JSON array) per
## line. The same replay always gives the same text; ReplayReader reads it back. A
## `"tilts"` record's frames are packed into one text (tilt_packing.gd).


## The file text for `replay`, ending in a newline.
static func write(replay: Replay) -> String:
	var header := (
		'{"replay": %d, "game": %s, "board": %s, "board_hash": %s, "mode": %s, "seed": %d, '
		+ '"step_hz": %d, "steps": %d, "state_hash": %d, "seconds": %s, "physics": %d, '
		+ '"rules": %d}'
	)
	var lines := PackedStringArray()
	(
		lines
		. append(
			(
				header
				% [
					Replay.VERSION,
					JSON.stringify(replay.game),
					JSON.stringify(replay.board_id),
					JSON.stringify(replay.board_hash),
					JSON.stringify(replay.mode_name()),
					replay.rng_seed,
					replay.step_hz,
					replay.steps,
					replay.state_hash,
					String.num(snappedf(replay.seconds, 0.001), 3),
					replay.physics_version,
					replay.rules_version,
				]
			)
		)
	)
	for record: Array in replay.records:
		if record[0] == "tilts":
			lines.append(JSON.stringify(["tilts", TiltPacking.encode(record.slice(1))]))
		else:
			lines.append(JSON.stringify(record))
	return "\n".join(lines) + "\n"
