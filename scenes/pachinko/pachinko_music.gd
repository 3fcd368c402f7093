extends MusicPlayer
## The pachinko game's music: the machine's loop, its mood following the bonus machine.
## A reach (the second reel stops matching the first) turns it to REACH; the spin's end to
## JACKPOT when all three match, else back to NORMAL; the last attacker closing after a
## jackpot, a new game and game over bring NORMAL back. Other signals (the jackpot rounds of
## issue 41) can call set_mood() the same way.

var _rules: PachinkoRules


## Follows the bonus machine of `rules` (a new game's rules each time); the mood starts NORMAL.
func bind(rules: PachinkoRules) -> void:
	_rules = rules
	set_mood(NORMAL)
	var bonus := rules.bonus
	bonus.reel_stopped.connect(_on_reel_stopped)
	bonus.reels_finished.connect(_on_reels_finished)
	bonus.attacker_changed.connect(_on_attacker_changed)
	rules.game_ended.connect(func(_summary: Dictionary) -> void: set_mood(NORMAL))


func _on_reel_stopped(reel: int, _symbol: int) -> void:
	if reel == 1 and _rules.bonus.reels.is_reach():
		set_mood(REACH)


func _on_reels_finished(_result: PackedInt32Array, jackpot: bool) -> void:
	# a spin that misses while a jackpot's attackers are still open keeps the jackpot music
	set_mood(JACKPOT if jackpot or _rules.bonus.any_attacker_open() else NORMAL)


func _on_attacker_changed(_index: int, open: bool) -> void:
	if not open and not _rules.bonus.any_attacker_open():
		set_mood(NORMAL)
