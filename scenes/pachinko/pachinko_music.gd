class_name PachinkoMusic
extends MusicPlayer
## The pachinko game's music: the machine's loop, its mood following the bonus machine.
## A reach (reach_started: two reels match) turns it to REACH; the reach's end to JACKPOT
## when the third matched too, else back to NORMAL; the jackpot stays JACKPOT through all
## its rounds (the attacker shuts between them) until jackpot_ended; a new game and game
## over bring NORMAL back.

var _rules: PachinkoRules


## Follows the bonus machine of `rules` (a new game's rules each time); the mood starts NORMAL.
func bind(rules: PachinkoRules) -> void:
	_rules = rules
	set_mood(NORMAL)
	var bonus := rules.bonus
	bonus.reach_started.connect(func() -> void: set_mood(REACH))
	bonus.reach_ended.connect(func(jackpot: bool) -> void: set_mood(JACKPOT if jackpot else NORMAL))
	bonus.jackpot_ended.connect(func(_paid: int) -> void: set_mood(NORMAL))
	rules.game_ended.connect(func(_summary: Dictionary) -> void: set_mood(NORMAL))
