#!/usr/bin/env bash
# Writes FOLDER/MANIFEST, which the launcher checks: one line a file, "size sha256 path"; a
# symbolic link is "link target path". Paths are relative to FOLDER, sorted.
# Usage: tools/release/manifest.sh FOLDER
set -euo pipefail
cd "$1"
part=$(mktemp) # outside the folder, so the listing never sees it
find . \( -type f -o -type l \) ! -name MANIFEST -printf '%P\n' | LC_ALL=C sort |
	while IFS= read -r f; do
		if [ -L "$f" ]; then
			printf 'link %s %s\n' "$(readlink "$f")" "$f"
		else
			printf '%s %s %s\n' "$(stat -c %s "$f")" "$(sha256sum "$f" | cut -d' ' -f1)" "$f"
		fi
	done >"$part"
mv "$part" MANIFEST
chmod 644 MANIFEST
