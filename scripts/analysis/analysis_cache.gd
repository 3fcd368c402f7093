class_name AnalysisCache
extends RefCounted
## Keeps analysis results per board content, so reopening a board shows its figures at
## once and any edit makes them stale: the key is a hash of the board's file text without
## its name lines and its payouts (ReportPayouts.geometry_text: a rename or "Save board
## as" keeps the figures, an undo back to analysed content finds them again, and a
## payout-only edit finds the counts, which ReportPayouts prices anew) and of the run's
## settings. Each entry is a JSON
## report and the heat-map PNG beside it, in user://analysis/. Read back as data only
## (JSON, PNG), never as code or resources.

## The cache folder.
const DEFAULT_FOLDER := "user://analysis"
## Another folder for tests ("" uses DEFAULT_FOLDER). Left at its type's default on purpose:
## the editor does not run the static initialisers of scripts that are not @tool.
static var folder_override := ""


## The cache key of an analysis of `plan`'s board with its settings.
static func key_for(plan: AnalysisPlan) -> String:
	var settings := (
		"v%d|%d|%d|%s|%s|%s"
		% [
			AnalysisReport.VERSION,
			plan.shots,
			plan.rng_seed,
			plan.power_from,
			plan.power_to,
			plan.played,
		]
	)
	return (ReportPayouts.geometry_text(plan.level) + "\n" + settings).sha256_text()


## Stores a report and its heat map under `key`. Returns OK or the file error.
static func save(key: String, report: Dictionary, heatmap: Image) -> Error:
	var made := DirAccess.make_dir_recursive_absolute(folder())
	if made != OK:
		return made
	var file := FileAccess.open(_path(key, "json"), FileAccess.WRITE)
	if file == null:
		return FileAccess.get_open_error()
	file.store_string(JSON.stringify(report))
	file.close()
	return heatmap.save_png(_path(key, "png")) if heatmap != null else OK


## The stored report for `key`, or {} when there is none or it is damaged.
static func load_report(key: String) -> Dictionary:
	var path := _path(key, "json")
	if not FileAccess.file_exists(path):
		return {}
	var parsed: Variant = JSON.parse_string(FileAccess.get_file_as_string(path))
	var report: Dictionary = parsed if parsed is Dictionary else {}
	if not _looks_like_report(report):
		push_warning("AnalysisCache: ignoring a damaged cache entry %s" % path)
		return {}
	return report


## The stored heat map for `key`, or null.
static func load_heatmap(key: String) -> Image:
	var path := _path(key, "png")
	if not FileAccess.file_exists(path):
		return null
	var image := Image.new()
	return image if image.load_png_from_buffer(FileAccess.get_file_as_bytes(path)) == OK else null


## The cached report for the editor's default analysis of `level`, priced with its
## payouts ({} when none yet).
static func cached_report(level: BoardLevel) -> Dictionary:
	if level == null or not level.is_pachinko():
		return {}
	var plan := AnalysisPlan.create(level, AnalysisPlan.EDITOR_SHOTS, 1)
	return ReportPayouts.repriced(load_report(key_for(plan)), level)


## Stores a maze analysis report (MazeAnalysis) for the board whose play_hash is `key`.
static func save_maze(key: String, report: Dictionary) -> Error:
	var made := DirAccess.make_dir_recursive_absolute(folder())
	if made != OK:
		return made
	var file := FileAccess.open(_path("maze_" + key, "json"), FileAccess.WRITE)
	if file == null:
		return FileAccess.get_open_error()
	file.store_string(JSON.stringify(report))
	file.close()
	return OK


## The stored maze analysis for `key`, or {} when there is none or it is damaged.
static func load_maze(key: String) -> Dictionary:
	var path := _path("maze_" + key, "json")
	if not FileAccess.file_exists(path):
		return {}
	var parsed: Variant = JSON.parse_string(FileAccess.get_file_as_string(path))
	var report: Dictionary = parsed if parsed is Dictionary else {}
	for mode: String in ["easy", "hard"]:
		var figures: Variant = report.get(mode)
		if not figures is Dictionary or not _has(figures, "games", TYPE_FLOAT):
			push_warning("AnalysisCache: ignoring a damaged cache entry %s" % path)
			return {}
		if not _has(figures, "holes", TYPE_ARRAY):
			push_warning("AnalysisCache: ignoring a damaged cache entry %s" % path)
			return {}
	return report


## The folder entries are kept in.
static func folder() -> String:
	return folder_override if not folder_override.is_empty() else DEFAULT_FOLDER


static func _path(key: String, ext: String) -> String:
	return folder().path_join("%s.%s" % [key.validate_filename(), ext])


# The fields the overlay and the warnings read, with the types they need.
static func _looks_like_report(report: Dictionary) -> bool:
	if report.get("version") != float(AnalysisReport.VERSION):
		return false
	for field: String in ["shots", "return", "return_ci95", "aim_tv"]:
		if not report.get(field) is float:
			return false
	for field: String in ["pockets", "bands", "dead_pockets"]:
		if not report.get(field) is Array:
			return false
	for pocket: Variant in report["pockets"]:
		if not _has(pocket, "rate", TYPE_FLOAT):
			return false
	for band: Variant in report["bands"]:
		if not _has(band, "pocket_rates", TYPE_ARRAY):
			return false
	return true


static func _has(item: Variant, field: String, type: Variant.Type) -> bool:
	if not item is Dictionary:
		return false
	var fields: Dictionary = item
	return typeof(fields.get(field)) == type
