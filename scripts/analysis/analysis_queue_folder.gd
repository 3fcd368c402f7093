class_name AnalysisQueueFolder
extends RefCounted
## The parent's side of a pooled run's queue folder (its files are listed in
## AnalysisQueueWorker): makes it with the board, the job and one todo file per range,
## reads the counts of finished ranges, puts ranges back for another worker, closes and
## removes it, and removes the folders of runs whose process is gone. AnalysisWorkerPool
## holds one per run and decides what to do; this only knows the files.

## The folder's absolute path ("" until `make`).
var path := ""
## The ranges' names (AnalysisQueueWorker.range_name), in chunk order.
var names := PackedStringArray()


## Removes the queue folders in `root` left by runs whose process is gone (a command line
## that was killed cannot clean up; its workers exit by themselves). Only where /proc tells
## which processes live; the folders are named `PID_USEC.queue`.
static func remove_stale(root: String) -> void:
	# No folder yet (a fresh user folder's first pooled run): nothing is stale.
	if not DirAccess.dir_exists_absolute("/proc/self") or not DirAccess.dir_exists_absolute(root):
		return
	for entry in DirAccess.get_directories_at(root):
		var owner := entry.get_slice("_", 0)
		if not entry.ends_with(".queue") or not owner.is_valid_int():
			continue
		if DirAccess.dir_exists_absolute("/proc/%s" % owner):
			continue
		var stale := root.path_join(entry)
		for file in DirAccess.get_files_at(stale):
			DirAccess.remove_absolute(stale.path_join(file))
		DirAccess.remove_absolute(stale)


## Makes the folder in AnalysisWorker.FOLDER (after clearing stale ones) for `plan`: the
## board's text when `with_board`, the job (`with_open`) and a todo file per range of
## `range_chunks` chunks; "" or what failed.
func make(plan: AnalysisPlan, with_open: bool, with_board: bool, range_chunks: int) -> String:
	var root := ProjectSettings.globalize_path(AnalysisWorker.FOLDER)
	remove_stale(root)
	path = root.path_join("%d_%d.queue" % [OS.get_process_id(), Time.get_ticks_usec()])
	if DirAccess.make_dir_recursive_absolute(path) != OK:
		return "could not make %s" % path
	if with_board:
		var text := BoardTextWriter.write(plan.level).to_utf8_buffer()
		if SafeWrite.write_bytes(path.path_join("board.board"), text) != OK:
			return "could not write the board in %s" % path
	var job := {"parent": OS.get_process_id(), "with_open": with_open}
	if (
		SafeWrite.write_bytes(path.path_join("job.json"), JSON.stringify(job).to_utf8_buffer())
		!= OK
	):
		return "could not write the job in %s" % path
	for first in range(0, plan.chunk_count(), range_chunks):
		var last := mini(first + range_chunks, plan.chunk_count()) - 1
		var name := AnalysisQueueWorker.range_name(first, last)
		names.append(name)
		if SafeWrite.write_bytes(path.path_join("todo_" + name), PackedByteArray()) != OK:
			return "could not write the queue in %s" % path
	return ""


## The board `make` wrote, as a path a worker's BoardLoader takes.
func board_path() -> String:
	return AnalysisWorker.FOLDER.path_join(path.get_file()).path_join("board.board")


## The names of the files in the folder now.
func files() -> PackedStringArray:
	return DirAccess.get_files_at(path)


## The counts of range `r` once its files are among `files`: [counts, open counts (null
## without `with_open`)], either null when its file could not be read; [] before.
func counts_of(r: int, files_now: PackedStringArray, with_open: bool) -> Array:
	var shut := "done_%s.tally" % names[r]
	var open := "done_%s.open.tally" % names[r]
	if not files_now.has(shut) or (with_open and not files_now.has(open)):
		return []
	var counts := AnalysisTally.from_bytes(FileAccess.get_file_as_bytes(path.path_join(shut)))
	var open_counts: AnalysisTally = null
	if with_open:
		open_counts = AnalysisTally.from_bytes(FileAccess.get_file_as_bytes(path.path_join(open)))
	return [counts, open_counts]


## Range `r` again, its unreadable counts dropped: back in the queue.
func retry(r: int) -> void:
	DirAccess.remove_absolute(path.path_join("done_%s.tally" % names[r]))
	SafeWrite.write_bytes(path.path_join("todo_" + names[r]), PackedByteArray())


## Worker `k`'s beat among `files_now` ("" before its first).
func beat(k: int, files_now: PackedStringArray) -> String:
	var beat_path := path.path_join("beat_%d" % k)
	return FileAccess.get_file_as_string(beat_path) if files_now.has(beat_path.get_file()) else ""


## The ranges worker `k` took, by the files among `files_now`.
func taken_by(k: int, files_now: PackedStringArray) -> PackedInt32Array:
	var out := PackedInt32Array()
	var prefix := "took_%d_" % k
	for file in files_now:
		if file.begins_with(prefix):
			var r := names.find(file.trim_prefix(prefix))
			if r >= 0:
				out.append(r)
	return out


## The chunks of `ranges` as a report names them: "7", "4-5", joined by ", ".
func chunks_text(ranges: PackedInt32Array) -> String:
	var parts := PackedStringArray()
	for r in ranges:
		var chunks := AnalysisQueueWorker.chunks_of(names[r])
		if chunks.size() == 1:
			parts.append(str(chunks[0]))
		else:
			parts.append("%d-%d" % [chunks[0], chunks[chunks.size() - 1]])
	return ", ".join(parts)


## Puts range `r`, taken by worker `k`, back in the queue.
func give_back(k: int, r: int) -> void:
	DirAccess.rename_absolute(
		path.path_join("took_%d_%s" % [k, names[r]]), path.path_join("todo_" + names[r])
	)


## Tells the workers there is no more work.
func close() -> void:
	SafeWrite.write_bytes(path.path_join("closed"), PackedByteArray())


## Removes the folder and its files (nothing when there is none).
func remove() -> void:
	if path.is_empty() or not DirAccess.dir_exists_absolute(path):
		return
	for file in DirAccess.get_files_at(path):
		DirAccess.remove_absolute(path.path_join(file))
	DirAccess.remove_absolute(path)
