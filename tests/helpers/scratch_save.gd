extends RefCounted
## A fresh player save for a test that plays with progress: swap_in() puts one stored at a
## scratch path in App.save_data (boards locked as for a new player) and returns the real
## one; restore() puts the real one back and deletes the scratch file.


## Swaps App.save_data for a fresh save stored at `path`; returns the real one.
static func swap_in(path: String) -> RefCounted:
	var real: RefCounted = App.save_data
	var scratch := SaveData.new()
	scratch.load_file(path)
	App.save_data = scratch
	App.settings.unlock_all_boards = false
	return real


## Puts `real` back as App.save_data and deletes the scratch save at `path`.
static func restore(real: RefCounted, path: String) -> void:
	App.save_data = real
	App.settings.unlock_all_boards = false
	DirAccess.remove_absolute(path)
