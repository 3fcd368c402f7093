class_name HouseJackpot
extends RefCounted
## A safety net for a new player: on a reel machine (Fever, Hanami), once a game has fired
## HOUSE_AFTER_SHOTS shots without a jackpot, its next start-pocket hit is a reach that lands
## one, once a board (kept in the save file when it lands). Trial 5: at 2.1 to 2.8 jackpots
## an hour a 20-minute first session could end without ever seeing the game's peak; trial 6:
## given on the first hit (shot 18) it read as a giveaway, so it waits for the unlucky.
## It is outside the machine's odds: the analysis and the autoplay never ask for it, so
## their return and jackpot figures leave it out (once a board in a player's life). Trial 8:
## announced as "First jackpot on the house!" it read as a giveaway, so nothing says it: the
## reach plays out as any other and the jackpot looks like any other.
## Shots a game fires without a jackpot before the house steps in: about 3 to 5 minutes of
## streaming, so a 20-minute first session still meets it and a lucky one never does.
const HOUSE_AFTER_SHOTS := 150


## Watches `rules`' game when the player has not had the house's jackpot yet on its board
## (and the game gives them: App.house_jackpots): its shot HOUSE_AFTER_SHOTS, with no jackpot
## yet, grants the next spin a jackpot. True when it watches. The save file keeps it once it
## lands, so a game that ends before it lands keeps the offer.
static func offer(rules: PachinkoRules) -> bool:
	var board_id := rules.level.board_id
	if not App.house_jackpots or not BonusGeometry.has_reels(rules.level):
		return false
	if App.save_data.has_had_house_jackpot(board_id):
		return false
	rules.ball_launched.connect(_on_shot.bind(rules))
	rules.bonus.house_jackpot_landed.connect(App.save_data.note_house_jackpot.bind(board_id))
	return true


static func _on_shot(_id: int, _power: float, _speed: float, rules: PachinkoRules) -> void:
	var bonus := rules.bonus
	if rules.ledger.shots < HOUSE_AFTER_SHOTS or bonus.jackpots > 0 or bonus.has_house_jackpot():
		return
	bonus.grant_house_jackpot()  # its jackpot ends the watch: bonus.jackpots > 0
