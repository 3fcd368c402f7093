#!/usr/bin/env bash
# make release: builds build/release/board-studio-<version>-linux-x86_64.tar.gz, one folder a
# player unpacks and starts with ./board-studio on any x86_64 Linux with X11 or Wayland.
#
# The game runs on Debian's Godot release template, which links ~80 libraries of Debian sid
# (glibc 2.43). The folder carries all of them, sid's loader and Mesa's GL drivers, taken from
# the setup's private Godot prefix (tools/setup.sh export). The launcher starts the game as
# `engine/board-studio --library-path engine/lib engine/godot`, where engine/board-studio is
# the dynamic loader under the game's name: Godot looks for its pack beside the program the
# kernel started, which is the loader, so the pack is engine/board-studio.pck. Nothing in the
# folder names a path of this machine: RPATHs are removed, the runtime's interpreter is a
# relative name, and libraries are found through --library-path only.
#
# Needs: make export's output (build/export/), patchelf, the prefix of tools/setup.sh.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
cd "$ROOT"
HERE=tools/release
die() { printf '\nrelease failed: %s\n\n' "$*" >&2; exit 1; }
say() { printf 'release: %s\n' "$*"; }

[ -f build/tools.env ] || die "no build/tools.env: run 'make setup' first."
GODOT=$(sed -n 's/^GODOT=//p' build/tools.env)
PREFIX=$(sed -n 's/^GODOT_PREFIX=//p' build/tools.env)
SYSROOT=$PREFIX/root
LIBDIR=$SYSROOT/usr/lib/x86_64-linux-gnu
LOADER=$LIBDIR/ld-linux-x86-64.so.2
[ -x "$LOADER" ] || die "the setup's Godot prefix ($PREFIX) has no loader: the release is built from Debian's Godot that 'tools/setup.sh export' unpacks (unset GODOT and run 'make setup')."
command -v patchelf >/dev/null || die "patchelf is missing (apt-get install patchelf)."

version=$(sed -n 's/^config\/version="\(.*\)"$/\1/p' project.godot)
[ -n "$version" ] || die "project.godot has no config/version."
commit=$(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)
git diff --quiet HEAD 2>/dev/null || commit="$commit (with uncommitted changes)"
NAME=board-studio-$version
OUT=build/release
STAGE=$OUT/$NAME
ARCHIVE=$OUT/$NAME-linux-x86_64.tar.gz
rm -rf "$OUT"
mkdir -p "$STAGE/engine/lib" "$STAGE/licenses"
ENGINE=$STAGE/engine
EXPORT=$OUT/export
tools/export.sh --unpatched "$EXPORT" >/dev/null || die "the export failed (above)."

# --- the runtime, its pack and the loader -------------------------------------------------
cp "$EXPORT/board_studio.x86_64" "$ENGINE/godot"
# the folder's loader starts it; its own interpreter entry only names that loader
patchelf --set-interpreter lib/ld-linux-x86-64.so.2 "$ENGINE/godot"
cp "$EXPORT/board_studio.pck" "$ENGINE/board-studio.pck"
rm -rf "$EXPORT"
say "exported the game (${SECONDS} s)"
cp "$LOADER" "$ENGINE/board-studio"
chmod 755 "$ENGINE/board-studio" "$ENGINE/godot"

# --- the libraries: the ldd closure of the runtime and of Mesa's GL -----------------------
# Mesa: glvnd's libGL / libGLX / libEGL and Mesa's vendor libraries, which link libgallium:
# every Mesa driver (llvmpipe, the software renderer, and the GPU drivers) is inside it since
# Mesa 24.2, so no dri/*_dri.so is ever loaded (the running game maps none). libudev: SDL
# loads it for gamepads.
GL_ROOTS=(libGL.so.1 libGLX.so.0 libGLX_mesa.so.0 libEGL.so.1 libEGL_mesa.so.0 libGLdispatch.so.0
	libudev.so.1)
search=$LIBDIR:$LIBDIR/pulseaudio
closure() { # elf... -> resolved paths of every library they need
	local f
	for f in "$@"; do
		"$LOADER" --library-path "$search" --list "$f" | awk '$2 == "=>" { print $3 }'
	done
}
roots=("$ENGINE/godot")
for lib in "${GL_ROOTS[@]}"; do roots+=("$LIBDIR/$lib"); done
if closure "${roots[@]}" | grep -q 'not$'; then
	closure "${roots[@]}" >&2 || true
	die "some libraries are missing from the prefix (above)."
fi
mapfile -t libs < <(closure "${roots[@]}" | sort -u)
for lib in "${GL_ROOTS[@]}"; do libs+=("$LIBDIR/$lib"); done
for path in "${libs[@]}"; do
	case $path in "$SYSROOT"/*) ;; *) die "$path is not in the prefix: the closure must not reach the host." ;; esac
	cp -L "$path" "$ENGINE/lib/$(basename "$path")"
done
# the loader is also lib/ld-linux-x86-64.so.2 (one file, two names): the runtime's interpreter
ln -f "$ENGINE/board-studio" "$ENGINE/lib/ld-linux-x86-64.so.2"
mkdir -p "$ENGINE/share/glvnd/egl_vendor.d"
cp "$SYSROOT/usr/share/glvnd/egl_vendor.d/50_mesa.json" "$ENGINE/share/glvnd/egl_vendor.d/"

# --- strip, drop every RPATH (they name the prefix) ----------------------------------------
before=$(du -sb "$ENGINE" | cut -f1)
while IFS= read -r -d '' f; do
	case $f in "$ENGINE/board-studio" | */ld-linux-x86-64.so.2) continue ;; esac # the loader: as shipped
	strip --strip-unneeded "$f" 2>/dev/null || die "strip failed on $f."
	# the setup pinned some to the prefix: overwrite that path in place, then drop the entry
	if [ -n "$(patchelf --print-rpath "$f" 2>/dev/null)" ]; then
		patchelf --set-rpath '$ORIGIN' "$f" && patchelf --remove-rpath "$f"
	fi
done < <(find "$ENGINE" -type f \( -name '*.so*' -o -name godot \) -print0)
# libc.so.6 can run as a program: its interpreter is the loader beside it
patchelf --set-interpreter ld-linux-x86-64.so.2 "$ENGINE/lib/libc.so.6"
after=$(du -sb "$ENGINE" | cut -f1)
say "stripped: $((before / 1048576)) MB -> $((after / 1048576)) MB"

# --- quiet defaults for what a player's system may lack -----------------------------------
mkdir -p "$ENGINE/share/fontconfig" "$ENGINE/share/alsa" "$ENGINE/share/X11"
cp "$HERE/files/fonts.conf" "$ENGINE/share/fontconfig/"
cp "$HERE/files/alsa.conf" "$ENGINE/share/alsa/"
cp -r "$SYSROOT/usr/share/X11/locale" "$ENGINE/share/X11/"

# --- the player's files --------------------------------------------------------------------
cp "$HERE/files/board-studio" "$STAGE/board-studio"
chmod 755 "$STAGE/board-studio"
sed "s/@VERSION@/$version/g" "$HERE/files/README.txt" >"$STAGE/README.txt"
cp "$HERE/files/board-studio.desktop" "$STAGE/"
printf 'Board Studio %s\ncommit %s\nbuilt %s\ngodot %s\n' "$version" "$commit" \
	"$(date -u +%Y-%m-%d)" "$("$GODOT" --headless --version 2>/dev/null | tail -n 1)" >"$STAGE/VERSION"
"$GODOT" --headless --path . -s "res://$HERE/icon_png.gd" -- "$ROOT/$STAGE/board-studio.png" \
	>/dev/null 2>&1 || die "Godot could not draw icon.svg into board-studio.png."
[ -s "$STAGE/board-studio.png" ] || die "the icon was not written."

# --- licences: Godot's and every bundled library's Debian copyright file -------------------
python3 "$HERE/licences.py" "$SYSROOT" "$ENGINE/lib" "$STAGE/licenses" ||
	die "a bundled library has no licence notice (above)."

# --- the manifest the launcher checks, then the archive ------------------------------------
say "folder ready (${SECONDS} s)"
"$HERE/manifest.sh" "$STAGE"
python3 "$HERE/elf_paths.py" --forbid "$PREFIX" --forbid "$ROOT" "$STAGE" || die "an ELF in the folder names a path outside it (above)."
tar -C "$OUT" --owner=0 --group=0 --numeric-owner -czf "$ARCHIVE" "$NAME"
say "$ARCHIVE (${SECONDS} s): $(du -m "$ARCHIVE" | cut -f1) MB packed, $(du -sm "$STAGE" | cut -f1) MB unpacked"
say "largest files:"
(cd "$STAGE" && find . -type f -printf '%s %P\n' | sort -rn | head -n 8 |
	awk '{ printf "  %6.1f MB  %s\n", $1 / 1048576, $2 }')
