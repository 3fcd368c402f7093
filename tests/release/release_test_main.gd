extends Node
## The test pack's first scene (make test's release run, tools/release_tests.sh): starts
## GUT's command-line runner inside Godot's release export template, which cannot run
## `-s gut_cmdln.gd` (script and pack overrides are compiled out of it). The test pack's
## project settings point `application/run/main_scene` here through the feature tag
## "release_tests" that only the "Tests" export preset has; GUT reads its options from the
## arguments after `--`. The fixtures the export leaves out (tools/fixture_pack.gd) are
## loaded first from `fixtures.pck` beside the test binary. GUT looks a test script up as a
## file, and an exported script is no file (it is `name.gdc` behind `name.gd.remap`), so every
## script named by `-gtest=a.gd,b.gd` is loaded here first: GUT then finds it in the cache.

const KnownEngineErrors := preload("res://tests/release/known_engine_errors.gd")

## The fixture pack's file name, beside the test binary.
const FIXTURE_PACK := "fixtures.pck"
# Keeps every loaded test script in the resource cache until GUT has run.
var _loaded_scripts: Array[Script] = []


func _ready() -> void:
	var pack := OS.get_executable_path().get_base_dir().path_join(FIXTURE_PACK)
	if not ProjectSettings.load_resource_pack(pack, false):
		printerr("release tests: cannot load %s (tools/fixture_pack.gd makes it)" % pack)
		get_tree().quit(1)
		return
	for path in _named_test_scripts():
		var script := load(path) as Script
		if script == null:
			printerr("release tests: cannot load %s" % path)
			get_tree().quit(1)
			return
		_loaded_scripts.append(script)
	var runner: Node = load("res://addons/gut/cli/gut_cli.gd").new()
	runner.ready.connect(_start.bind(runner), CONNECT_ONE_SHOT)
	get_tree().root.add_child.call_deferred(runner)


# Starts GUT with the known-error logger after GUT's own tracker (see its header): the
# tracker is registered here first, which GUT's own later registration leaves as it is.
func _start(runner: Node) -> void:
	GutErrorTracker.register_logger(GutUtils.get_error_tracker())
	OS.add_logger(KnownEngineErrors.new())
	runner.call("main")


# The scripts named by -gtest= (GUT's own option, comma-separated) among the arguments.
func _named_test_scripts() -> PackedStringArray:
	var named := PackedStringArray()
	for arg in OS.get_cmdline_args():
		if arg.begins_with("-gtest="):
			named.append_array(arg.trim_prefix("-gtest=").split(",", false))
	return named
