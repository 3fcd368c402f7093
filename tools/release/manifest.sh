#!/usr/bin/env bash
# Writes FOLDER/MANIFEST, which the launcher checks: one line a file, "size sha256 path",
# paths relative to FOLDER, sorted. The folder holds no symbolic links (a link would escape
# the launcher's size check), so one is an error.
# Usage: tools/release/manifest.sh FOLDER
set -euo pipefail
cd "$1"
links=$(find . -type l -printf '%P ')
[ -z "$links" ] || { echo "manifest: the folder must hold no symbolic links: $links" >&2; exit 1; }
part=$(mktemp) # outside the folder, so the listing never sees it
find . -type f ! -name MANIFEST -printf '%P\n' | LC_ALL=C sort |
	while IFS= read -r f; do
		printf '%s %s %s\n' "$(stat -c %s "$f")" "$(sha256sum "$f" | cut -d' ' -f1)" "$f"
	done >"$part"
mv "$part" MANIFEST
chmod 644 MANIFEST
