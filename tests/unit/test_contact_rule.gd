extends GutTest
## The contact rule every contact asks: a ball that comes in faster than the bounce
## threshold bounces, a ball resting on a surface settles instead of hopping on the spot
## (what gravity added in this step does not count toward its approach).

## The bounce threshold of these cases, px/s.
const THRESHOLD := 50.0


func test_a_ball_coming_in_faster_than_the_threshold_bounces() -> void:
	assert_true(ContactRule.bounces(-100.0, 0.0, THRESHOLD))
	assert_true(ContactRule.bounces(-50.05, 0.0, THRESHOLD), "a hair over the threshold")


func test_a_ball_at_or_under_the_threshold_does_not_bounce() -> void:
	assert_false(ContactRule.bounces(-50.0, 0.0, THRESHOLD), "exactly the threshold")
	assert_false(ContactRule.bounces(-10.0, 0.0, THRESHOLD))
	assert_false(ContactRule.bounces(30.0, 0.0, THRESHOLD), "a ball moving away")


func test_what_gravity_added_this_step_does_not_make_a_resting_ball_bounce() -> void:
	# 60 px/s in, 30 of them from gravity this step: 30 of its own, under the threshold
	assert_false(ContactRule.bounces(-60.0, -30.0, THRESHOLD))
	assert_true(ContactRule.bounces(-90.0, -30.0, THRESHOLD), "60 of its own: it bounces")
	assert_false(ContactRule.bounces(-80.0, -30.0, THRESHOLD), "50 of its own: just not")


func test_gravity_pulling_away_from_the_surface_takes_nothing_off() -> void:
	assert_true(ContactRule.bounces(-50.05, 30.0, THRESHOLD), "gravity away adds nothing")
	assert_false(ContactRule.bounces(-40.0, 30.0, THRESHOLD), "nor lifts a slow ball over")
	assert_false(ContactRule.bounces(-49.95, 30.0, THRESHOLD), "not even a hair under")
