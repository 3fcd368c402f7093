#!/usr/bin/env bash
# Prints the path of a clean Debian 12 (bookworm) root for the release check: made once with
# debootstrap (minbase: no X, no GL, no Godot) from this machine's Debian mirror and cached
# outside the checkout, in ~/.cache/board-studio/bookworm-root. The check never changes it:
# each run unpacks the release into a scratch folder inside it and removes that afterwards.
# Exits 77 with the reason on stderr when it cannot be had here (not root, no debootstrap and
# no apt-get, the Debian archive unreachable).
set -euo pipefail
CACHE=${BOARD_STUDIO_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/board-studio}
ROOTFS=$CACHE/bookworm-root
skip() { printf '%s\n' "$*" >&2; exit 77; }

if [ -f "$ROOTFS.complete" ]; then echo "$ROOTFS"; exit 0; fi
[ "$(id -u)" = 0 ] || skip "making and entering a Debian 12 root (debootstrap, chroot) needs root"
if ! command -v debootstrap >/dev/null; then
	command -v apt-get >/dev/null || skip "no debootstrap and no apt-get to install it"
	apt-get update -qq >/dev/null 2>&1 || true
	DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap >/dev/null 2>&1 ||
		skip "apt-get could not install debootstrap"
fi
mirror=$(awk '/^URIs:/{print $2; exit}' /etc/apt/sources.list.d/debian.sources 2>/dev/null || true)
[ -n "$mirror" ] || mirror=$(awk '/^deb /{print $2; exit}' /etc/apt/sources.list 2>/dev/null || true)
[ -n "$mirror" ] || skip "no Debian mirror configured in /etc/apt (debootstrap needs one)"
mkdir -p "$CACHE"
(
	flock 9
	[ -f "$ROOTFS.complete" ] && exit 0
	stage=$ROOTFS.staging
	rm -rf "$stage" "$ROOTFS"
	echo "release-check: making a clean Debian 12 root with debootstrap (once, about 2 min)" >&2
	if ! debootstrap --variant=minbase bookworm "$stage" "$mirror" >"$CACHE/bookworm-root.log" 2>&1; then
		rm -rf "$stage"
		skip "debootstrap could not build a Debian 12 root from $mirror (log: $CACHE/bookworm-root.log)"
	fi
	mv "$stage" "$ROOTFS"
	touch "$ROOTFS.complete"
) 9>"$ROOTFS.lock"
echo "$ROOTFS"
