class_name SlowMotion
extends Node
## Slow motion for the last balls of a game: when the player has LAST_BALLS or fewer balls
## left to shoot and a ball in play is about to drop into a pocket (PocketApproach), the
## game's clock eases down to SLOW_SCALE, holds while that ball is still on its way in (at
## most MAX_HOLD), and eases back to full speed. Only the clock slows: the game runs the
## same fixed steps, fewer of them per frame, so a replay and the state hash never know.
## The game asks `update()` once a frame for the factor to scale its frame time by.

## The slow motion began for ball `ball_id`.
signal started(ball_id: int)
## The clock is back at full speed.
signal ended

enum Phase { IDLE, EASE_IN, HOLD, EASE_OUT }

## Balls left to shoot (cup and launcher) at or under which a game is in its last balls.
const LAST_BALLS := 2
## Balls in play at or under which the game is in its last balls (a stream from the handle
## with a nearly empty cup is not yet the end: measured on Fever, slowing then came 14 times
## a game and held 19% of the time).
const MAX_IN_PLAY := 3
## How fast the clock runs at the slowest.
const SLOW_SCALE := 0.3
## Real seconds to slow down and to speed up again.
const EASE_IN := 0.12
const EASE_OUT := 0.35
## The most real seconds the clock stays slow for one ball.
const MAX_HOLD := 1.2
## Real seconds the clock stays slow after the ball went in (the catch is seen slowly).
const AFTER_CATCH := 0.2
## Real seconds after one slow motion ends before another may begin.
const COOLDOWN := 3.0

## Times the slow motion began since the game scene started (the play report reads it).
var triggers := 0

var _phase := Phase.IDLE
var _scale := 1.0
var _age := 0.0
var _cooldown := 0.0
var _ball := -1
## The ball followed last: one ball is slowed for once (a ball rattling round a mouth's rim
## would slow the game again and again).
var _last_ball := -1
var _linger := 0.0
var _approach: PocketApproach
var _sounds: SoundBank


## Plays the slow-motion sound on `sounds` (null: silent).
func set_sounds(sounds: SoundBank) -> void:
	_sounds = sounds


## Watches the pockets of `rules`' board (a new game's rules each time); full speed now.
func bind(rules: PachinkoRules) -> void:
	_approach = PocketApproach.new(rules.level, rules.world.tuning.gravity)
	_finish()
	_cooldown = 0.0
	_last_ball = -1


## True while the clock runs slower than full speed.
func is_slow() -> bool:
	return _phase != Phase.IDLE


## The ball the slow motion follows, or -1.
func followed_ball() -> int:
	return _ball if is_slow() else -1


## The clock's factor now, 1 at full speed.
func time_scale() -> float:
	return _scale


## True when `rules`' game is in its last balls: playing, with one to MAX_IN_PLAY balls in
## play and at most LAST_BALLS left to shoot.
static func in_last_balls(rules: PachinkoRules) -> bool:
	if rules.state != PachinkoRules.State.PLAYING:
		return false
	if rules.balls_in_play() == 0 or rules.balls_in_play() > MAX_IN_PLAY:
		return false
	return rules.cup + (1 if rules.loaded else 0) <= LAST_BALLS


## Moves the slow motion on by `real_delta` seconds of real time and returns the factor
## for this frame's game time (1 at full speed, never under SLOW_SCALE).
func update(rules: PachinkoRules, real_delta: float) -> float:
	if rules == null or _approach == null or rules.state != PachinkoRules.State.PLAYING:
		_finish()
		return _scale
	_age += real_delta
	_cooldown = maxf(_cooldown - real_delta, 0.0)
	match _phase:
		Phase.IDLE:
			_look_for_ball(rules)
		Phase.EASE_IN, Phase.HOLD:
			_follow(rules, real_delta)
		Phase.EASE_OUT:
			_scale = lerpf(SLOW_SCALE, 1.0, clampf(_age / EASE_OUT, 0.0, 1.0))
			if _age >= EASE_OUT:
				_finish()
	return _scale


func _look_for_ball(rules: PachinkoRules) -> void:
	if _cooldown > 0.0 or not in_last_balls(rules):
		return
	var ball := _approach.find_ball(rules.world, rules.bonus, _last_ball)
	if ball < 0:
		return
	_ball = ball
	_last_ball = ball
	_phase = Phase.EASE_IN
	_age = 0.0
	_linger = AFTER_CATCH
	triggers += 1
	if _sounds != null:
		_sounds.play(SoundBank.SLOW_MO, -4.0)
	started.emit(ball)


func _follow(rules: PachinkoRules, real_delta: float) -> void:
	if _phase == Phase.EASE_IN:
		_scale = lerpf(1.0, SLOW_SCALE, clampf(_age / EASE_IN, 0.0, 1.0))
		if _age >= EASE_IN:
			_phase = Phase.HOLD
	var on_its_way := _approach.ball_entering(rules.world, _ball, rules.bonus)
	if not on_its_way:
		_linger -= real_delta
	if _linger <= 0.0 or _age >= MAX_HOLD:
		_ease_out()


func _ease_out() -> void:
	# From wherever the clock is now: the ease out starts at the same speed.
	_phase = Phase.EASE_OUT
	_age = EASE_OUT * inverse_lerp(SLOW_SCALE, 1.0, _scale)


func _finish() -> void:
	var was_slow := _phase != Phase.IDLE
	_phase = Phase.IDLE
	_scale = 1.0
	_age = 0.0
	_ball = -1
	if was_slow:
		_cooldown = COOLDOWN
		ended.emit()
