extends GutTest
## The menus' falling balls stay behind every menu's text: a blind trial saw them drawn over
## the board list's "My boards" heading. The backdrop draws on a canvas layer below the one
## holding the menu's labels and buttons, whatever order their nodes come in.

const MENUS: Array[String] = [
	"res://scenes/menu/main_menu.tscn",
	"res://scenes/menu/level_select.tscn",
	"res://scenes/menu/settings_menu.tscn",
]


# The canvas layer `item` draws on (0: the window's own canvas).
func _layer(item: CanvasItem) -> int:
	var layer := item.get_canvas_layer_node()
	return layer.layer if layer != null else 0


func _walk(node: Node, found: Array[Node]) -> void:
	found.append(node)
	for child in node.get_children():
		_walk(child, found)


func test_the_backdrop_is_below_every_label_and_button_of_each_menu() -> void:
	for path in MENUS:
		var menu: Control = (load(path) as PackedScene).instantiate()
		add_child_autofree(menu)
		await get_tree().process_frame
		var nodes: Array[Node] = []
		_walk(menu, nodes)
		var backdrops := nodes.filter(func(node: Node) -> bool: return node is MenuBackdrop)
		assert_eq(backdrops.size(), 1, "%s has its backdrop" % path.get_file())
		if backdrops.is_empty():
			continue
		var below := _layer(backdrops[0])
		var texts := 0
		for node in nodes:
			if node is Label or node is Button:
				texts += 1
				assert_lt(
					below,
					_layer(node),
					"%s: the backdrop is under %s" % [path.get_file(), menu.get_path_to(node)]
				)
		assert_gt(texts, 2, "%s: its words were found" % path.get_file())


# Trial 5: the balls still showed between the level cards, falling through the card list.
# The level select keeps the pins and the gradient but no ball falls there; the title keeps
# its balls.
func test_no_ball_falls_on_the_level_select() -> void:
	var expected := {
		"res://scenes/menu/main_menu.tscn": true,
		"res://scenes/menu/level_select.tscn": false,
	}
	for path: String in expected:
		var menu: Control = (load(path) as PackedScene).instantiate()
		add_child_autofree(menu)
		await get_tree().process_frame
		var nodes: Array[Node] = []
		_walk(menu, nodes)
		var backdrops := nodes.filter(func(node: Node) -> bool: return node is MenuBackdrop)
		var balls: int = (backdrops[0] as MenuBackdrop).ball_count()
		assert_eq(balls > 0, expected[path], "%s: %d falling balls" % [path.get_file(), balls])
