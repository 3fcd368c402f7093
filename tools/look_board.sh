# Sourced by tools/maze_look.sh and tools/pachinko_look.sh: a scratch user folder for one
# look at a board, so the player's own settings and best results stay out of it, with a
# play-test request that opens board BOARD of game KIND ("maze" or "pachinko"). Sets
# SCRATCH (removed on exit) and USERDIR, and exports XDG_DATA_HOME.
# Display: XVFB_NUM is the first X display number xvfb-run tries (99 unless set).
look_board_setup() {
	local kind=$1 board=$2
	SCRATCH=$(mktemp -d)
	trap 'rm -rf "$SCRATCH"' EXIT
	USERDIR="$SCRATCH/godot/app_userdata/Board Studio"
	mkdir -p "$USERDIR"
	printf '{"format": 1, "board": "res://levels/%s/%s.board", "kind": "%s", "written_at": %s}\n' \
		"$kind" "$board" "$kind" "$(date +%s)" >"$USERDIR/playtest_request.json"
	export XDG_DATA_HOME="$SCRATCH"
}
