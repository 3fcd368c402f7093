class_name BoardPieces
extends RefCounted
## What a pachinko board is made of, for a player: the kinds of piece it has (only those),
## each with one line saying what it does, in the board's own numbers. The instructions
## panel shows them, each beside a small drawing (piece_icon.gd).

enum Piece { POCKET, START, ATTACKER, TULIP, WINDMILL }


## The kinds of piece `level` has, in the order a player meets them.
static func of(level: BoardLevel) -> Array[Piece]:
	var found: Array[Piece] = []
	# A ball meets the windmills in the field before it reaches any pocket.
	if not level.windmills.is_empty():
		found.append(Piece.WINDMILL)
	if not level.pockets.is_empty():
		found.append(Piece.POCKET)
	for piece: Piece in [Piece.START, Piece.ATTACKER, Piece.TULIP]:
		if not _bonus_of(level, piece).is_empty():
			found.append(piece)
	return found


## One line about `piece` on `level`, with its payout (the range when they differ).
static func line(level: BoardLevel, piece: Piece) -> String:
	match piece:
		Piece.POCKET:
			var pays: Array[int] = []
			for spec in level.pockets:
				pays.append(spec.payout)
			return "Pocket: a ball that drops in pays %s back into the tray." % _balls(pays)
		Piece.START:
			return (
				(
					"START pocket: pays %s and spins the three reels; three equal numbers are a"
					% _balls(_payouts(level, piece))
				)
				+ " jackpot. REACH! means the first two match: the last reel decides."
			)
		Piece.ATTACKER:
			return (
				"ATTACKER: a jackpot swings its gold lid open for a few seconds; each ball it"
				+ " catches then pays %s." % _balls(_payouts(level, piece))
			)
		Piece.TULIP:
			return (
				(
					"Tulip: pays %s; a catch opens its petals so it catches more, the next one"
					% _balls(_payouts(level, piece))
				)
				+ " shuts them."
			)
		Piece.WINDMILL:
			return _windmill_line(level)
	return ""


# Driven wheels (red hub) turn by themselves; free ones (brass hub) only when struck. The line
# names the kinds the board has.
static func _windmill_line(level: BoardLevel) -> String:
	var driven := false
	var free := false
	for spec in level.windmills:
		if spec == null:
			continue
		if spec.free_spin:
			free = true
		else:
			driven = true
	var start := "Windmill: its spinning blades knock a ball aside and change where it falls"
	if driven and free:
		return start + "; a red hub turns by itself, a brass one only when balls hit it."
	if free:
		return start + "; it only turns when balls hit it."
	return start + "."


## The bonus pockets of `level` that are `piece` (a bonus kind).
static func bonus_specs(level: BoardLevel, piece: Piece) -> Array[BonusPocketSpec]:
	return _bonus_of(level, piece)


static func _bonus_of(level: BoardLevel, piece: Piece) -> Array[BonusPocketSpec]:
	var role := -1
	match piece:
		Piece.START:
			role = BonusPocketSpec.Role.START
		Piece.ATTACKER:
			role = BonusPocketSpec.Role.ATTACKER
		Piece.TULIP:
			role = BonusPocketSpec.Role.TULIP
	var specs: Array[BonusPocketSpec] = []
	for spec in level.bonus_pockets:
		if spec != null and spec.role == role:
			specs.append(spec)
	return specs


static func _payouts(level: BoardLevel, piece: Piece) -> Array[int]:
	var pays: Array[int] = []
	for spec in _bonus_of(level, piece):
		pays.append(spec.payout)
	return pays


# "3 balls", "2 to 4 balls", "1 ball".
static func _balls(pays: Array[int]) -> String:
	if pays.is_empty():
		return "balls"
	var low: int = pays.min()
	var high: int = pays.max()
	if low == high:
		return "%d ball%s" % [low, "" if low == 1 else "s"]
	return "%d to %d balls" % [low, high]
