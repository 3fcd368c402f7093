extends RefCounted
## The house rules over a set of scripts: no file uses a file of a higher layer, and no files
## need each other, directly or round a loop. Pure: it is given the files' texts, so a test
## can also feed it a made-up breach and see it named.

const ScriptReferences := preload("res://tests/unit/layering/script_references.gd")
const LayerList := preload("res://tests/unit/layering/layer_list.gd")

## Per file (path relative to res://): {used path: first line using it}. Filled by check().
var uses := {}
## The loops found, each as its files in order (one per group of files that need each other).
var cycles: Array[PackedStringArray] = []


## Every breach among `files` ({path relative to res://: text}), one line each, naming both
## files and the line; `autoloads` maps each autoload name to its path. Empty when all keep
## the rules.
func check(files: Dictionary, layers: LayerList, autoloads: Dictionary) -> PackedStringArray:
	var names := autoloads.duplicate()
	for path: String in files:
		var declared := ScriptReferences.declared_class(files[path])
		if not declared.is_empty():
			names[declared] = path
	var paths: Array = files.keys()
	paths.sort()
	for path: String in paths:
		var used := ScriptReferences.uses(files[path], path, names)
		for target: String in used.keys():
			if not files.has(target):
				used.erase(target)
		uses[path] = used
	var out := PackedStringArray()
	for path: String in paths:
		var own := layers.layer_of(path)
		if own == 0:
			out.append("%s is in no layer: add its folder to docs/architecture.md's list" % path)
			continue
		for target: String in uses[path]:
			var theirs := layers.layer_of(target)
			if theirs > own:
				out.append(
					(
						(
							"%s:%d uses %s, a higher layer: %s is in %s"
							% [path, uses[path][target], target, target, layers.describe(theirs)]
						)
						+ ", %s in %s" % [path, layers.describe(own)]
					)
				)
	cycles = _find_cycles(paths)
	for loop in cycles:
		out.append("file cycle: " + _describe_loop(loop))
	return out


# "a.gd:3 uses b.gd, b.gd:9 uses a.gd".
func _describe_loop(loop: PackedStringArray) -> String:
	var steps := PackedStringArray()
	for k in loop.size():
		var here := loop[k]
		var next := loop[(k + 1) % loop.size()]
		steps.append("%s:%d uses %s" % [here, uses[here][next], next])
	return ", ".join(steps)


# One loop per strongly connected group of two or more files (Tarjan's algorithm), each the
# shortest loop through the group's first file by name.
func _find_cycles(paths: Array) -> Array[PackedStringArray]:
	var state := {"next": 0, "index": {}, "low": {}, "stack": [], "on_stack": {}, "groups": []}
	for path: String in paths:
		if not state.index.has(path):
			_connect(path, state)
	var loops: Array[PackedStringArray] = []
	for group: Array in state.groups:
		if group.size() > 1:
			group.sort()
			loops.append(_shortest_loop(group[0], group))
	return loops


func _connect(path: String, state: Dictionary) -> void:
	state.index[path] = state.next
	state.low[path] = state.next
	state.next += 1
	state.stack.append(path)
	state.on_stack[path] = true
	for target: String in uses[path]:
		if not state.index.has(target):
			_connect(target, state)
			state.low[path] = mini(state.low[path], state.low[target])
		elif state.on_stack.has(target):
			state.low[path] = mini(state.low[path], state.index[target])
	if state.low[path] != state.index[path]:
		return
	var group := []
	while true:
		var member: String = state.stack.pop_back()
		state.on_stack.erase(member)
		group.append(member)
		if member == path:
			break
	state.groups.append(group)


# Breadth first from `start` through the group's files back to `start`.
func _shortest_loop(start: String, group: Array) -> PackedStringArray:
	var came_from := {}
	var queue: Array[String] = [start]
	while not queue.is_empty():
		var here: String = queue.pop_front()
		for target: String in uses[here]:
			if target == start:
				var loop := PackedStringArray([here])
				while loop[0] != start:
					loop.insert(0, came_from[loop[0]])
				return loop
			if group.has(target) and not came_from.has(target):
				came_from[target] = here
				queue.append(target)
	return PackedStringArray([start])
