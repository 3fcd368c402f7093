#!/usr/bin/env bash
# Screenshot of the board editor after a play analysis: opens the Godot editor under Xvfb
# on a board scene (SCENE=, pachinko classic by default; a maze scene analyses the maze), presses Analyze in the board dock (the hook
# tools/shots/editor_analysis_hook.gd), waits for the run and saves the editor window.
#   tools/editor_analysis_shot.sh [out.png]     default build/shots/editor_analysis.png
# EDITOR_ANALYSIS_IDLE_EDITOR=1 times the run with the editor in its default low-processor mode
# (it draws what changes, as a designer's editor does) instead of drawing every frame.
# EDITOR_ANALYSIS_WORKER=1 runs it in a worker process (AnalysisWorker), =0 on the editor's
# threads (unset: the analysis panel's default); EDITOR_ANALYSIS_POOL=N on N worker processes
# beside the editor's own share (AnalysisWorkerPool); the log line says which.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
SIZE=${SIZE:-1600x900}
SCENE=${SCENE:-res://scenes/boards/pachinko_classic.tscn}
OUT=${1:-build/shots/editor_analysis.png}
mkdir -p "$(dirname "$OUT")" build
# Start with no scene open, and put the developer's editor session back afterwards.
LAYOUT=.godot/editor/editor_layout.cfg
saved_layout=$(mktemp)
[ -f "$LAYOUT" ] && cp "$LAYOUT" "$saved_layout"
[ ! -f "$LAYOUT" ] || sed -i '/^open_scenes=/d; /^current_scene=/d' "$LAYOUT"
restore() {
	if [ -s "$saved_layout" ]; then cp "$saved_layout" "$LAYOUT"; else rm -f "$LAYOUT"; fi
	rm -f "$saved_layout"
}
trap restore EXIT
rm -f "$OUT"
log=build/editor-analysis-shot.log
GODOT_PICTURES=1 BOARD_EDITOR_HOOK=res://tools/shots/editor_analysis_hook.gd \
	BOARD_EDITOR_ANALYSIS_SHOT="$SCENE;res://$OUT" timeout 320 \
	xvfb-run -a -s "-screen 0 ${SIZE}x24" tools/godot.sh --editor \
	--rendering-driver opengl3 --resolution "$SIZE" --path . >"$log" 2>&1 || true
if [ ! -f "$OUT" ]; then
	echo "editor_analysis_shot: no $OUT (log: $log)" >&2
	grep -E 'SCRIPT ERROR|Analysis shot' "$log" | head -20 >&2
	exit 1
fi
grep -E 'Analysis shot' "$log" || true
echo "editor_analysis_shot: wrote $OUT"
