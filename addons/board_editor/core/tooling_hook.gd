extends RefCounted
## The one hook for tooling (screenshots, the editor self-check): when the editor starts with
## BOARD_EDITOR_HOOK naming a script under res://tools/ or res://tests/, the plugin adds it
## as a child Node, built with the plugin as its only argument. Nothing in the shipped game
## uses it.

const ENV := "BOARD_EDITOR_HOOK"
const FOLDERS: Array[String] = ["res://tools/", "res://tests/"]


## Adds the hook the environment names to `plugin`, if any; a path outside FOLDERS, or a
## script that is not a Node, is refused with an error naming it.
static func attach(plugin: Node) -> void:
	var path := OS.get_environment(ENV)
	if path.is_empty():
		return
	var allowed := FOLDERS.any(func(folder: String) -> bool: return path.begins_with(folder))
	if not allowed or path.contains("..") or not ResourceLoader.exists(path):
		push_error("%s must name a script under %s, got '%s'." % [ENV, FOLDERS, path])
		return
	var script := load(path) as GDScript
	var hook: Object = script.new(plugin) if script != null else null
	if hook is Node:
		plugin.add_child(hook as Node)
	else:
		push_error("%s: %s is not a Node script." % [ENV, path])
