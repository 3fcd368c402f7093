#!/usr/bin/env bash
# Runs the Godot that `make setup` found or installed (recorded in build/tools.env):
#   tools/godot.sh ARGS...    headless runs, the game window, the editor, pictures alike
#
# Which GL stack, and why. The setup's own Godot is Debian sid's build, patched to load sid's
# loader and libraries from the private prefix through a forced RPATH. Whatever GL it loads
# runs on sid's libc, so it always gets sid's Mesa from the same prefix (tools/setup.sh
# installs it with the binary), never the host's:
#   - Mixed stacks broke. Once the prefix held sid's libGL, the RPATH picked it while its
#     dependencies fell back to the host: libLLVM's own RUNPATH hid the prefix, so Mesa failed
#     to load, GLX found no config and Godot died with SIGSEGV in its GLES fallback.
#   - With nothing GL in the prefix the host's Mesa 22.3 did run (llvmpipe, GL 4.5), but only
#     on top of sid's libc, libdrm and libxcb, a pairing nobody tests or ships.
#   - Measured under Xvfb, 1280x720, main menu, 15 s, 2 busy cores: host Mesa 22.3.6 and sid
#     Mesa 26.2.6 both gave 20-45 FPS (noise dominates) and about 290-310 MB resident;
#     sid's also reports GL 4.6. Same speed, so the stack that matches the binary wins.
# No LD_LIBRARY_PATH: every child (sh from OS.execute, the editor's scans) would inherit it
# and die on sid's libc ("symbol lookup error ... __tunable_is_initialized", 224 lines per
# editor run before). The setup pins the prefix's libraries that carry their own RUNPATH
# (libLLVM, libpulse) to the prefix instead, so the RPATH alone finds everything.
# Mesa 26 keeps its drivers in libgallium, found that way too: LIBGL_DRIVERS_PATH is read
# by no library in the prefix, and it would point host GL programs started from the editor
# at drivers they cannot load, so it stays unset. The one variable set is glvnd's EGL vendor
# folder (EGL is used on Wayland and as the GLES fallback): the prefix's 50_mesa.json names
# libEGL_mesa.so.0, which the RPATH resolves in the prefix; a host child resolves the same
# name to its own Mesa, so it is harmless there. GLX needs nothing: glvnd asks the X server
# for its vendor and loads libGLX_<vendor>.so.0, sid's Mesa for Xvfb or the host's
# libGLX_nvidia on an NVIDIA desktop.
# A Godot of your own ($GODOT or PATH) runs untouched, on your system's GL.
# GODOT_PICTURES=1 is still accepted (tools/shots.sh sets it) and changes nothing any more.
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
