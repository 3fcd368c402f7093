@tool
class_name MazeGenSettings
extends RefCounted
## What the maze generator is asked for: the grid, how many black holes, how hard, and the
## seed that makes the same request give the same maze. `problem()` names anything out of
## range before a maze is built.

const MIN_CELLS := 4
const MAX_CELLS := 40
## Most holes per cell of the grid (a quarter): more would leave no maze to play.
const MAX_HOLE_SHARE := 0.25

## Cells across and down (each cell is a 25 px corridor plus a 10 px wall).
var cols := 10
var rows := 9
## Black holes wanted (hard mode); fewer are placed when more would cut a start off.
var holes := 6
## 0 = many loops and holes only in dead ends; 1 = few loops and holes in the corridors.
var difficulty := 0.5
## The random seed: the same settings and seed always give the same maze.
var rng_seed := 1
## The board's id without the "maze_" prefix, its title and its blurb.
var id := "generated"
var title := "Generated maze"
var blurb := ""


## Takes the values of a dictionary with any of the keys cols, rows, holes, difficulty,
## seed, id, title, blurb (missing keys keep their values); returns self for chaining.
func read(values: Dictionary) -> RefCounted:
	var cols_value: int = values.get("cols", cols)
	var rows_value: int = values.get("rows", rows)
	var holes_value: int = values.get("holes", holes)
	var difficulty_value: float = values.get("difficulty", difficulty)
	var seed_value: int = values.get("seed", rng_seed)
	cols = cols_value
	rows = rows_value
	holes = holes_value
	difficulty = difficulty_value
	rng_seed = seed_value
	id = str(values.get("id", id))
	title = str(values.get("title", title))
	blurb = str(values.get("blurb", blurb))
	return self


## The most holes a grid of these settings may ask for.
func max_holes() -> int:
	return floori(cols * rows * MAX_HOLE_SHARE)


## "" when the settings can be built, else what is wrong, for the person who asked.
func problem() -> String:
	if cols < MIN_CELLS or cols > MAX_CELLS or rows < MIN_CELLS or rows > MAX_CELLS:
		return (
			"A generated maze needs %d to %d columns and rows (got %d × %d)."
			% [MIN_CELLS, MAX_CELLS, cols, rows]
		)
	if holes < 0 or holes > max_holes():
		return (
			"Black holes must be 0 to %d on a %d × %d maze (got %d)."
			% [max_holes(), cols, rows, holes]
		)
	if not is_finite(difficulty) or difficulty < 0.0 or difficulty > 1.0:
		return "Difficulty must be between 0 and 1 (got %s)." % difficulty
	if id.is_empty() or title.is_empty():
		return "A generated maze needs an id and a title."
	return ""
