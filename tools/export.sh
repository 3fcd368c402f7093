#!/usr/bin/env bash
# Builds the Linux x86_64 game into build/export/ with the "Linux" preset of
# export_presets.cfg (make export runs `tools/setup.sh export` first).
#
# Godot looks for its export templates in ~/.local/share/godot/export_templates/<version>/.
# When the setup's private prefix holds Debian's templates (godot-template-release/-debug),
# they are linked there under the version Godot reports, and the exported binary is patched
# like the setup's godot (private loader and libraries) so it runs on this machine. When
# that folder already holds real template files (Godot's official ones), they are used as
# they are: nothing is linked or patched.
#
#   tools/export.sh                  build/export/, patched to run on this machine
#   tools/export.sh --unpatched DIR  DIR/, the binary left as the template made it (make release)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
ENV_FILE=build/tools.env
die() { printf '\nexport failed: %s\n\n' "$*" >&2; exit 1; }
[ -f "$ENV_FILE" ] || die "no build/tools.env: run 'make setup' first."
GODOT=$(sed -n 's/^GODOT=//p' "$ENV_FILE")
PREFIX=$(sed -n 's/^GODOT_PREFIX=//p' "$ENV_FILE")
OUT=build/export
allow_patch=1
if [ "${1:-}" = --unpatched ]; then
	[ -n "${2:-}" ] || die "--unpatched needs a folder."
	OUT=$2
	allow_patch=0
fi
BINARY=$OUT/board_studio.x86_64

# "4.6.3.stable.debian4.6.3+ds-3" -> "4.6.3.stable": the folder name Godot looks in
version=$("$GODOT" --headless --version 2>/dev/null | tail -n 1)
version=$(printf '%s' "$version" | sed -E 's/^([0-9]+\.[0-9]+(\.[0-9]+)?\.[a-z0-9]+).*/\1/')
[ -n "$version" ] || die "could not read Godot's version from $GODOT."
TEMPLATES=${XDG_DATA_HOME:-$HOME/.local/share}/godot/export_templates/$version
DEBIAN_RELEASE=$PREFIX/root/usr/bin/godot-template-release
DEBIAN_DEBUG=$PREFIX/root/usr/bin/godot-template-debug
patch_for_here=0
if [ -f "$TEMPLATES/linux_release.x86_64" ] && [ ! -L "$TEMPLATES/linux_release.x86_64" ]; then
	echo "export: using the export templates installed in $TEMPLATES"
elif [ -x "$DEBIAN_RELEASE" ]; then
	mkdir -p "$TEMPLATES"
	ln -sfn "$DEBIAN_RELEASE" "$TEMPLATES/linux_release.x86_64"
	[ -x "$DEBIAN_DEBUG" ] && ln -sfn "$DEBIAN_DEBUG" "$TEMPLATES/linux_debug.x86_64"
	patch_for_here=1
elif [ ! -e "$TEMPLATES/linux_release.x86_64" ]; then
	die "no Linux export template: neither Debian's ($DEBIAN_RELEASE, from 'tools/setup.sh export') nor Godot's official ones in $TEMPLATES. Install the official export templates for $version (Godot editor: Editor > Manage Export Templates) and run 'make export' again."
fi

rm -rf "$OUT"
mkdir -p "$OUT"
# the export runs the editor, which re-saves project.godot in its own layout (dropping
# comments and default values): put the committed text back afterwards
saved_project=$(mktemp)
cp project.godot "$saved_project"
restore_project() {
	cmp -s "$saved_project" project.godot || cp "$saved_project" project.godot
	rm -f "$saved_project"
}
trap restore_project EXIT
log=$(mktemp)
echo "export: building $BINARY with Godot $version"
if ! timeout 600 "$GODOT" --headless --path . --export-release "Linux" "$BINARY" >"$log" 2>&1; then
	cat "$log" >&2; rm -f "$log"
	die "Godot's export step failed (log above)."
fi
if grep -qE 'SCRIPT ERROR|Parse Error|ERROR: .*[Ee]xport' "$log"; then
	grep -E -A2 'SCRIPT ERROR|Parse Error|ERROR: .*[Ee]xport' "$log" | head -30 >&2
	rm -f "$log"
	die "Godot reported errors while exporting (above)."
fi
rm -f "$log"
[ -x "$BINARY" ] && [ -f "$OUT/board_studio.pck" ] || die "the export produced no $BINARY + .pck."

if [ "$patch_for_here" = 1 ] && [ "$allow_patch" = 1 ]; then
	command -v patchelf >/dev/null || die "patchelf is missing (apt-get install patchelf)."
	L=$PREFIX/root/usr/lib/x86_64-linux-gnu
	# Debian's template links sid's libraries: give it the private loader and libraries
	patchelf --set-interpreter "$L/ld-linux-x86-64.so.2" --force-rpath \
		--set-rpath "$L:$L/pulseaudio" "$BINARY"
	echo "export: patched $BINARY to use $L (runs on this machine only)"
fi
ls -l "$OUT"
