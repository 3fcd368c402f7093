extends Node
## The one autoload. Starts the headless autoplay when the command line asks for it.
## (The shell issue grows this: settings, save data, board catalog, play-test hand-off.)

const AutoplayCli := preload("res://scripts/app/autoplay_cli.gd")


func _ready() -> void:
	var args := OS.get_cmdline_user_args()
	if AutoplayCli.wants_autoplay(args):
		var code := AutoplayCli.run(args)
		get_tree().quit(code)
