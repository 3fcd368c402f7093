class_name MinHeap
extends RefCounted
## A binary min-heap of (cost, node) pairs: the frontier of the maze pilot's searches
## (MazeSlidePlanner's best-first plans, MazeNav's distance field). pop() gives the node of
## least cost; last_cost is that node's cost.

## The cost of the node the last pop() returned.
var last_cost := 0.0
var _cost := PackedFloat32Array()
var _node := PackedInt32Array()


## True when no node is left.
func is_empty() -> bool:
	return _node.is_empty()


## Adds `node` with `cost`.
func push(cost: float, node: int) -> void:
	var m := _node.size()
	_cost.append(cost)
	_node.append(node)
	while m > 0:
		var parent := (m - 1) >> 1
		if _cost[parent] <= cost:
			break
		_cost[m] = _cost[parent]
		_node[m] = _node[parent]
		m = parent
	_cost[m] = cost
	_node[m] = node


## Takes out the node of least cost (ties in no set order) and returns it.
func pop() -> int:
	var top := _node[0]
	last_cost = _cost[0]
	var size := _node.size() - 1
	var tail_cost := _cost[size]
	var tail_node := _node[size]
	_cost.resize(size)
	_node.resize(size)
	if size == 0:
		return top
	var k := 0
	while true:
		var child := 2 * k + 1
		if child >= size:
			break
		if child + 1 < size and _cost[child + 1] < _cost[child]:
			child += 1
		if tail_cost <= _cost[child]:
			break
		_cost[k] = _cost[child]
		_node[k] = _node[child]
		k = child
	_cost[k] = tail_cost
	_node[k] = tail_node
	return top
