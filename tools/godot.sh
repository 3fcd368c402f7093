#!/usr/bin/env bash
# Runs the Godot that `make setup` found or installed (recorded in build/tools.env):
#   tools/godot.sh ARGS...    headless runs, the game window, the editor, pictures alike
#
# Which GL stack, and why. The setup's own Godot is Debian sid's build, patched to load sid's
# loader and libraries from the private prefix through a forced RPATH, so whatever GL it
# loads runs on sid's libc. tools/setup.sh installs sid's Mesa beside it, always, and that is
# what it uses, whatever ran before:
#   - A mixed stack crashed: once `make shots` had put sid's libGL in the prefix, libLLVM's
#     own RUNPATH hid the prefix from its dependencies, Mesa failed to load, GLX found no
#     config and Godot died with SIGSEGV in its GLES fallback.
#   - With no GL in the prefix the host's Mesa 22.3 did run, but on top of sid's libc, libdrm
#     and libxcb: a pairing nobody tests or ships.
#   - Measured under Xvfb (1280x720, main menu, 600 frames, 3 runs each, 2 busy cores):
#     host Mesa 22.3.6 19.7-20.1 s CPU, ~280 MB resident; sid Mesa 26.2.6 17.6-19.8 s CPU,
#     ~302 MB, GL 4.6 instead of 4.5. Same cost, so the stack that matches the binary wins.
# No LD_LIBRARY_PATH: every child (sh from OS.execute, the editor's scans) would inherit it
# and die on sid's libc ("symbol lookup error ... __tunable_is_initialized": 224 lines in a
# 25 s editor run under Xvfb before, 0 now). The setup pins the prefix's libraries that carry
# their own RUNPATH (libLLVM, libpulse) to the prefix instead, so the RPATH finds everything.
# Mesa 26 builds its drivers into libgallium, found the same way: no library in the prefix
# reads LIBGL_DRIVERS_PATH, and host GL programs started from the editor would, so it stays
# unset. GLX needs nothing (glvnd loads libGLX_<vendor of the X server>.so.0: sid's Mesa
# under Xvfb, the host's libGLX_nvidia on an NVIDIA desktop). The one variable set is glvnd's
# EGL vendor folder (EGL serves Wayland and the GLES fallback): the prefix's 50_mesa.json
# only names libEGL_mesa.so.0, which a host child would resolve to its own Mesa.
# A Godot of your own ($GODOT or PATH) runs untouched, on your system's GL.
# GODOT_PICTURES=1 (set by tools/shots.sh) is no longer needed and changes nothing.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
ENV_FILE=$ROOT/build/tools.env
if [ ! -f "$ENV_FILE" ]; then
	echo "tools/godot.sh: run 'make setup' first (no build/tools.env)." >&2
	exit 1
fi
GODOT=$(sed -n 's/^GODOT=//p' "$ENV_FILE")
PREFIX=$(sed -n 's/^GODOT_PREFIX=//p' "$ENV_FILE")
if [ "$GODOT" = "$PREFIX/godot" ]; then
	export __EGL_VENDOR_LIBRARY_DIRS=$PREFIX/root/usr/share/glvnd/egl_vendor.d
fi
exec "$GODOT" "$@"
