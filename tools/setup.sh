#!/usr/bin/env bash
# Sets up everything the project needs, idempotently, and records where it put it.
#
#   tools/setup.sh            Godot 4.6+, GUT, gdtoolkit, the import step
#   tools/setup.sh pictures   also Mesa for Godot and the host's Xvfb (make shots)
#   tools/setup.sh export     also Debian's Linux export templates (make export)
#
# Godot: $GODOT, or `godot` on PATH, when it reports 4.6 or newer; otherwise Debian's own
# build (sid) unpacked into a private prefix under the cache folder and patched to use its
# own loader and libraries. Everything downloaded is staged and only moved into place once
# it works, so an interrupted run never leaves a state the next run trusts.
# Writes build/tools.env (GODOT=..., GDLINT=..., GDFORMAT=...) for the Makefile.
set -euo pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
CACHE=${BOARD_STUDIO_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/board-studio}
PREFIX=$CACHE/godot-4.6
GUT_VERSION=9.6.0
GDTOOLKIT_VERSION=4.5.0
WANT=${1:-base}

say() { printf 'setup: %s\n' "$*" >&2; }
die() { printf '\nsetup failed: %s\n\n' "$*" >&2; exit 1; }

version_ok() { # "4.6.3.stable..." -> true when major.minor >= 4.6
	local v=$1 major minor
	major=${v%%.*}; minor=${v#*.}; minor=${minor%%.*}
	[[ $major =~ ^[0-9]+$ && $minor =~ ^[0-9]+$ ]] || return 1
	((major > 4 || (major == 4 && minor >= 6)))
}

need_host_package() { # command package
	command -v "$1" >/dev/null 2>&1 && return 0
	if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null; then
		say "installing host package $2"
		apt-get update -qq >/dev/null 2>&1 || true
		DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "$2" >/dev/null ||
			die "apt-get could not install '$2'. Install it yourself (apt-get install $2) and run 'make setup' again."
	else
		die "the host program '$1' is missing. Install the Debian package '$2' (sudo apt-get install $2), then run 'make setup' again."
	fi
}

apt_private() { # apt-get/apt-cache against sid, with the prefix's own lists
	local tool=$1; shift
	"$tool" -o Dir::Etc::sourcelist="$PREFIX.apt/sources.list" -o Dir::Etc::sourceparts=/dev/null \
		-o Dir::State::Lists="$PREFIX.apt/lists" -o Dir::State::status=/dev/null \
		-o Dir::Cache="$PREFIX.apt/cache" -o Debug::NoLocking=1 "$@"
}

apt_private_update() {
	# lists younger than a day are reused (find_godot runs in a subshell, so no flag survives)
	if [ -n "$(find "$PREFIX.apt/lists" -maxdepth 1 -name '*Packages*' -mmin -1440 2>/dev/null | head -n 1)" ]; then
		return 0
	fi
	mkdir -p "$PREFIX.apt/lists/partial" "$PREFIX.apt/cache/archives/partial"
	local mirror
	mirror=$(awk '/^URIs:/{print $2; exit}' /etc/apt/sources.list.d/debian.sources 2>/dev/null || true)
	[ -n "$mirror" ] || mirror=$(awk '/^deb /{print $2; exit}' /etc/apt/sources.list 2>/dev/null || true)
	[ -n "$mirror" ] || die "no Debian mirror found in /etc/apt/sources.list.d/debian.sources or /etc/apt/sources.list; set GODOT to a Godot 4.6+ binary instead."
	echo "deb [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] $mirror sid main" \
		>"$PREFIX.apt/sources.list"
	say "reading Debian sid's package lists (for Godot 4.6)"
	apt_private apt-get -qq update >/dev/null 2>&1 ||
		die "could not reach the Debian archive to fetch Godot 4.6. Either make it reachable, or install Godot 4.6+ yourself and run: GODOT=/path/to/godot make setup"
}

# Downloads packages (and their dependency closure when asked) and unpacks them into root/.
unpack_packages() { # stage closure|exact pkg...
	local stage=$1 mode=$2; shift 2
	local pkgs=("$@")
	if [ "$mode" = closure ]; then
		mapfile -t pkgs < <(apt_private apt-cache depends --recurse --no-recommends --no-suggests \
			--no-conflicts --no-breaks --no-replaces --no-enhances --no-pre-depends "$@" |
			grep -v '^[ <]' | sort -u |
			grep -vE '^(fonts-|cdebconf|debconf|libdebian-installer|libnewt|libslang|libtextwrap|fontconfig-config|libllvm|libgbm|libdrm|godot-|sse4)' || true)
		pkgs+=("$@")
	fi
	[ ${#pkgs[@]} -gt 0 ] || die "apt found no packages for: $*"
	mkdir -p "$stage/debs"
	say "downloading ${#pkgs[@]} Debian packages"
	(cd "$stage/debs" && apt_private apt-get -qq download "${pkgs[@]}" >/dev/null 2>&1) ||
		die "downloading Debian packages failed (${pkgs[*]:0:6} ...). Check that the Debian archive is reachable, or set GODOT to a Godot 4.6+ binary."
	local f
	for f in "$stage"/debs/*.deb; do dpkg -x "$f" "$stage/root"; done
	rm -rf "$stage/debs"
}

patch_binary() { # binary lib-dir
	patchelf --set-interpreter "$2/ld-linux-x86-64.so.2" --force-rpath \
		--set-rpath "$2:$2/pulseaudio" "$1"
}

install_godot() {
	need_host_package patchelf patchelf
	apt_private_update
	local stage=$PREFIX.staging
	rm -rf "$stage"; mkdir -p "$stage/root"
	unpack_packages "$stage" closure godot
	local lib=$PREFIX/root/usr/lib/x86_64-linux-gnu # final location, baked into the rpath
	cp "$stage/root/usr/bin/godot" "$stage/godot"
	patch_binary "$stage/godot" "$lib"
	local f
	for f in "$stage"/root/usr/lib/x86_64-linux-gnu/libpulse.so.0.* \
		"$stage"/root/usr/lib/x86_64-linux-gnu/libpulse-simple.so.0.*; do
		[ -e "$f" ] && patchelf --set-rpath "$lib/pulseaudio:$lib" "$f"
	done
	rm -rf "$PREFIX"; mv "$stage" "$PREFIX"
	local v
	v=$("$PREFIX/godot" --headless --version 2>/dev/null | tail -n 1) || true
	if ! version_ok "$v"; then
		rm -rf "$PREFIX"
		die "Debian's Godot unpacked but does not run here (it said: '${v:-nothing}'). Install Godot 4.6+ yourself and run: GODOT=/path/to/godot make setup"
	fi
	touch "$PREFIX/.complete"
	say "Godot $v installed in $PREFIX"
}

find_godot() {
	local candidate v
	for candidate in "${GODOT:-}" "$(command -v godot 2>/dev/null || true)"; do
		[ -n "$candidate" ] && [ -x "$candidate" ] || continue
		v=$("$candidate" --headless --version 2>/dev/null | tail -n 1) || true
		if version_ok "$v"; then echo "$candidate"; return 0; fi
		if [ "$candidate" = "${GODOT:-}" ]; then
			die "GODOT=$GODOT reports version '${v:-nothing}', but this project needs Godot 4.6 or newer. Point GODOT at a 4.6+ binary, or unset it to let the setup fetch Debian's build."
		fi
	done
	[ -f "$PREFIX/.complete" ] || install_godot
	echo "$PREFIX/godot"
}

install_extra() { # name pkg... : unpack extra sid packages into the prefix (Mesa, templates)
	local name=$1; shift
	[ -f "$PREFIX/.extra-$name" ] && return 0
	[ -f "$PREFIX/.complete" ] || die "the '$name' extras need the setup's own Godot prefix; unset GODOT and run 'make setup' first."
	apt_private_update
	local stage=$PREFIX.extra-staging
	rm -rf "$stage"; mkdir -p "$stage/root"
	unpack_packages "$stage" exact "$@"
	cp -a "$stage/root/." "$PREFIX/root/"
	rm -rf "$stage"
	touch "$PREFIX/.extra-$name"
}

install_gut() {
	local dest=$ROOT/addons/gut
	if [ -f "$dest/plugin.cfg" ] && grep -q "version=\"$GUT_VERSION\"" "$dest/plugin.cfg"; then
		return 0
	fi
	local archive=${GUT_ARCHIVE:-}
	[ -n "$archive" ] || archive=$ROOT/../shared/vendor/gut-$GUT_VERSION.tar.gz
	if [ ! -f "$archive" ]; then
		local cached=$CACHE/gut-$GUT_VERSION.tar.gz
		if [ ! -f "$cached" ]; then
			say "fetching GUT $GUT_VERSION from its upstream release"
			mkdir -p "$CACHE"
			curl -fsSL -o "$cached.part" \
				"https://github.com/bitwes/Gut/archive/refs/tags/v$GUT_VERSION.tar.gz" 2>/dev/null &&
				mv "$cached.part" "$cached" ||
				{ rm -f "$cached.part"; die "GUT $GUT_VERSION was not found: no ../shared/vendor/gut-$GUT_VERSION.tar.gz, no GUT_ARCHIVE, and the upstream release could not be downloaded. Download Gut v$GUT_VERSION (a .tar.gz of the release) and run: GUT_ARCHIVE=/path/to/gut-$GUT_VERSION.tar.gz make setup"; }
		fi
		archive=$cached
	fi
	local tmp
	tmp=$(mktemp -d)
	tar -xzf "$archive" -C "$tmp" || { rm -rf "$tmp"; die "the GUT archive '$archive' is not a readable .tar.gz."; }
	local found
	found=$(find "$tmp" -path '*/addons/gut/plugin.cfg' | head -n 1)
	[ -n "$found" ] || { rm -rf "$tmp"; die "the GUT archive '$archive' has no addons/gut/plugin.cfg inside."; }
	rm -rf "$dest"; mkdir -p "$ROOT/addons"
	mv "$(dirname "$found")" "$dest"
	rm -rf "$tmp"
	say "GUT $GUT_VERSION unpacked into addons/gut"
}

install_gdtoolkit() {
	local venv=$CACHE/gdtoolkit-$GDTOOLKIT_VERSION
	# the marker is written last: a half-made venv is never trusted
	if [ ! -f "$venv/.complete" ]; then
		say "installing gdtoolkit $GDTOOLKIT_VERSION into $venv"
		rm -rf "$venv"
		python3 -m venv "$venv" ||
			die "python3 -m venv failed; install python3-venv (apt-get install python3-venv) and run 'make setup' again."
		"$venv/bin/pip" install -q "gdtoolkit==$GDTOOLKIT_VERSION" >/dev/null ||
			{ rm -rf "$venv"; die "pip could not install gdtoolkit==$GDTOOLKIT_VERSION from PyPI (needed by make lint / make test)."; }
		touch "$venv/.complete"
	fi
	echo "$venv/bin"
}

import_project() { # godot: rebuild the class cache when sources changed since the last import
	local stamp=$ROOT/.godot/.setup-import-stamp
	if [ -f "$stamp" ] && [ -f "$ROOT/.godot/global_script_class_cache.cfg" ] &&
		[ -z "$(find "$ROOT/project.godot" "$ROOT/scripts" "$ROOT/scenes" "$ROOT/addons" \
			"$ROOT/levels" "$ROOT/tests" "$ROOT/assets" -newer "$stamp" \
			\( -name '*.gd' -o -name '*.tscn' -o -name '*.tres' -o -name '*.godot' \
			-o -name '*.svg' -o -name '*.png' -o -name '*.wav' -o -name '*.cfg' \) \
			-print -quit 2>/dev/null)" ]; then
		return 0
	fi
	say "importing the project (class cache, resources)"
	local log
	log=$(mktemp)
	mkdir -p "$ROOT/.godot"
	# one import at a time: parallel runs (several shells, make -j) share .godot/
	flock "$ROOT/.godot/.setup-import-lock" "$1" --headless --path "$ROOT" --import >"$log" 2>&1 || true
	if [ ! -f "$ROOT/.godot/global_script_class_cache.cfg" ] && grep -q class_name -r "$ROOT/scripts" 2>/dev/null; then
		cat "$log" >&2; rm -f "$log"
		die "Godot's import step did not build the class cache (log above)."
	fi
	rm -f "$log"
	touch "$stamp"
}

main() {
	local godot bin
	godot=$(find_godot)
	case $WANT in
	pictures)
		need_host_package xvfb-run xvfb
		[ -e /usr/lib/x86_64-linux-gnu/dri/swrast_dri.so ] ||
			need_host_package /usr/lib/x86_64-linux-gnu/dri/swrast_dri.so libgl1-mesa-dri
		if [ "$godot" = "$PREFIX/godot" ]; then
			install_extra mesa libgl1-mesa-dri libgl1 libegl1 libglx-mesa0 libegl-mesa0 \
				libglvnd0 libglx0 libgbm1 libllvm22 libdrm2 libdrm-common libdrm-amdgpu1 \
				libdrm-intel1 libvulkan1 libxcb-glx0 libxxf86vm1
		fi
		;;
	export)
		need_host_package patchelf patchelf
		install_extra templates godot-template-release godot-template-debug
		;;
	esac
	install_gut
	bin=$(install_gdtoolkit)
	mkdir -p "$ROOT/build"
	touch "$ROOT/build/.gdignore" # screenshots and reports are not game resources
	{
		echo "GODOT=$godot"
		echo "GODOT_PREFIX=$PREFIX"
		echo "GDLINT=$bin/gdlint"
		echo "GDFORMAT=$bin/gdformat"
	} >"$ROOT/build/tools.env.part"
	mv "$ROOT/build/tools.env.part" "$ROOT/build/tools.env"
	import_project "$godot"
}

main
