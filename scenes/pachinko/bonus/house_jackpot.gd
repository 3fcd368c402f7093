class_name HouseJackpot
extends RefCounted
## A jackpot a new player meets early: on a reel machine (Fever, Hanami) the first
## start-pocket hit of the player's first game there is a reach that lands a jackpot, once
## a board (kept in the save file when it lands). Trial 5: at 2.1 to 2.8 jackpots an hour a
## 20-minute first session could end without ever seeing the game's peak.
## It is a gift outside the machine's odds: the analysis and the autoplay never ask for it,
## so their return and jackpot figures leave it out (a jackpot pays about 110 balls at
## uniform power, once a board in a player's life).

## What the jackpot's banner says under "ROUND 1 / 10" when the house gave it.
const WORDS := "First jackpot on the house!"


## Grants `rules`' next spin a jackpot when the player has not had the house's yet on its
## board (and the game gives them: App.house_jackpots); true when it did. The save file
## keeps it once it lands, so a game that ends before its first start-pocket hit keeps it.
static func offer(rules: PachinkoRules) -> bool:
	var board_id := rules.level.board_id
	if not App.house_jackpots or not BonusGeometry.has_reels(rules.level):
		return false
	if App.save_data.has_had_house_jackpot(board_id):
		return false
	rules.bonus.grant_house_jackpot()
	rules.bonus.house_jackpot_landed.connect(App.save_data.note_house_jackpot.bind(board_id))
	return true
