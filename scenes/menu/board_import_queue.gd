class_name BoardImportQueue
extends RefCounted
## My boards imports off the main thread, for the level select: files wait in order, one
## worker thread reads, checks and copies each (UserBoards.import_result; a large board is
## slow to check), and when the queue runs dry the screen gets one line per file saying
## what happened to it. Files added while an import runs wait for it to finish.

## Game titles by kind name, for the line that sends a board to the other game's list.
var titles: Dictionary = {}

var _loading: BoardListLoading = null
var _waiting: Array[Dictionary] = []  # jobs not started yet
var _lines := PackedStringArray()  # what happened to each file imported so far
var _refused := false
var _listing_kind := ""


## Queues `sources` for the `kind` list, into `user_root`. Returns the status line to show
## when a new import starts ("Importing 2 files…"), or "" when they wait for one running.
func add(sources: PackedStringArray, kind: String, user_root: String) -> String:
	_listing_kind = kind
	for source in sources:
		_waiting.append({"path": source, "kind": BoardLevel.kind_named(kind), "root": user_root})
	return _start() if _loading == null else ""


## True while files are being imported or wait for it.
func is_busy() -> bool:
	return _loading != null


## Stops the import (its thread finishes in the background and is joined by the App).
func cancel() -> void:
	if _loading != null:
		_loading.cancel()
		_loading = null
	_waiting.clear()


## Takes what the thread finished. True once the whole queue is done: then report() and
## any_refused() say what happened, and the queue is ready for more.
func poll() -> bool:
	if _loading == null:
		return false
	for done in _loading.take_finished():
		var result: BoardLoadResult = done["result"]
		_lines.append(_line_for(result))
	if _loading.is_busy():
		return false
	if not _waiting.is_empty():
		_start()
		return false
	_loading = null
	return true


## One line per file of the finished queue; reading it starts the next report afresh.
func report() -> String:
	var text := "\n".join(_lines)
	_lines = PackedStringArray()
	return text


## True when a file of the finished queue was refused (read before report()).
func any_refused() -> bool:
	var refused := _refused
	_refused = false
	return refused


# One thread imports the waiting files in order (each picks a free file name in turn).
func _start() -> String:
	var jobs := _waiting
	_waiting = []
	_loading = BoardListLoading.new(jobs, UserBoards.import_result, 1)
	return "Importing %d file%s…" % [jobs.size(), "" if jobs.size() == 1 else "s"]


func _line_for(result: BoardLoadResult) -> String:
	if not result.ok():
		_refused = true
		return "Not imported: %s" % result.error
	var line := (
		'Imported "%s" into My boards as %s' % [result.level.display_name, result.path.get_file()]
	)
	var its_kind := BoardLevel.kind_name(result.level.kind)
	if its_kind != _listing_kind:
		line += " (a %s board: find it in the %s list)" % [its_kind, titles.get(its_kind, its_kind)]
	return line + "."
