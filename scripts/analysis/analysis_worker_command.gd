class_name AnalysisWorkerCommand
extends RefCounted
## The command line that starts one queue worker (AnalysisQueueWorker) of a pooled run:
## this binary, or in the release folder the bundled loader given its libraries and engine,
## then the project (editor build only) and the worker's own arguments.


## Starts worker `id` on the queue folder `queue` for `plan`, loading the board at `board`;
## its process id, or -1 when it did not start.
static func start(plan: AnalysisPlan, board: String, queue: String, id: int) -> int:
	var pid := OS.create_process(
		OS.get_executable_path(), program_prefix() + arguments(plan, board, queue, id)
	)
	return pid if pid > 0 else -1


## What goes before a worker's own arguments. In the release folder this process is the
## bundled loader named like the game (engine/board-studio, beside board-studio.pck and the
## engine binary `godot`), so a worker is the same loader given the libraries and the engine;
## the loader runs the engine in its own process, so the pid it gets can still be killed.
static func program_prefix() -> PackedStringArray:
	var exe := OS.get_executable_path()
	var folder := exe.get_base_dir()
	var engine := folder.path_join("godot")
	var pack := exe.get_basename() + ".pck"
	if (
		exe.get_file() != "godot"
		and FileAccess.file_exists(engine)
		and FileAccess.file_exists(pack)
	):
		return PackedStringArray(["--library-path", folder.path_join("lib"), engine])
	return PackedStringArray()


## Worker `id`'s arguments: the engine's, then the analysis command on queue `queue`.
static func arguments(
	plan: AnalysisPlan, board: String, queue: String, id: int
) -> PackedStringArray:
	var args := PackedStringArray(["--headless", "--quiet"])
	# The editor build runs the project folder; an exported game loads the pack beside its
	# binary by itself, and a release template refuses --path.
	if OS.has_feature("editor"):
		args.append_array(PackedStringArray(["--path", ProjectSettings.globalize_path("res://")]))
	(
		args
		. append_array(
			[
				"--",
				"--analyze=pachinko",
				"--board=%s" % board,
				"--shots=%d" % plan.shots,
				"--seed=%d" % plan.rng_seed,
				"--queue=%s" % queue,
				"--worker-id=%d" % id,
			]
		)
	)
	if plan.played:
		args.append("--played")
	return args
