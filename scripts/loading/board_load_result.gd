class_name BoardLoadResult
extends RefCounted
## What `BoardLoader.load_board` returns: either a usable `level` or an `error` that names
## the file and the problem (never both).

## The loaded, upgraded and validated board; null when loading failed.
var level: BoardLevel = null
## Empty on success, else a message naming the file and what is wrong with it.
var error: String = ""
## The file this result is about.
var path: String = ""
## Validator warnings (not fatal) found while loading, as BoardIssue objects.
var warnings: Array[BoardIssue] = []


## True when a level is available.
func ok() -> bool:
	return level != null and error.is_empty()
