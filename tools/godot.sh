#!/usr/bin/env bash
# Runs the Godot that `make setup` found or installed (recorded in build/tools.env).
#   tools/godot.sh ARGS...            headless-capable binary, host libraries untouched
#   GODOT_PICTURES=1 tools/godot.sh   also points GL/EGL at the private prefix's Mesa
# Only this process gets LD_LIBRARY_PATH: exporting it into a shell breaks host programs.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
ENV_FILE=$ROOT/build/tools.env
if [ ! -f "$ENV_FILE" ]; then
	echo "tools/godot.sh: run 'make setup' first (no build/tools.env)." >&2
	exit 1
fi
GODOT=$(sed -n 's/^GODOT=//p' "$ENV_FILE")
PREFIX=$(sed -n 's/^GODOT_PREFIX=//p' "$ENV_FILE")
if [ "${GODOT_PICTURES:-0}" = 1 ] && [ "$GODOT" = "$PREFIX/godot" ]; then
	L=$PREFIX/root/usr/lib/x86_64-linux-gnu
	export LD_LIBRARY_PATH=$L:$L/pulseaudio LIBGL_DRIVERS_PATH=$L/dri
	export __EGL_VENDOR_LIBRARY_DIRS=$PREFIX/root/usr/share/glvnd/egl_vendor.d
fi
exec "$GODOT" "$@"
