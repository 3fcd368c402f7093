extends GutTest
## KeyNames: on-screen help names the key the player has bound, and says something a player
## can read when an action has no key.


func after_each() -> void:
	if InputMap.has_action(&"test_key_names_action"):
		InputMap.erase_action(&"test_key_names_action")


func test_the_first_bound_key_is_named_and_follows_a_remap() -> void:
	InputMap.add_action(&"test_key_names_action")
	assert_eq(KeyNames.of(&"test_key_names_action", "the test key"), "the test key", "no key yet")
	var pad := InputEventJoypadButton.new()
	InputMap.action_add_event(&"test_key_names_action", pad)
	var key := InputEventKey.new()
	key.physical_keycode = KEY_H
	InputMap.action_add_event(&"test_key_names_action", key)
	assert_eq(KeyNames.of(&"test_key_names_action"), "H", "a pad button is passed over")
	key.keycode = KEY_J
	assert_eq(KeyNames.of(&"test_key_names_action"), "J", "the key's own code wins")


func test_an_unknown_action_gives_the_fallback() -> void:
	assert_eq(KeyNames.of(&"no_such_action", "the start key"), "the start key")
