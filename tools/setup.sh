#!/usr/bin/env bash
# Sets up everything the project needs, idempotently, and records where it put it.
#
#   tools/setup.sh            Godot 4.6+ (with its GL stack), GUT, gdtoolkit, the import step
#   tools/setup.sh test       also the host's Xvfb for the play check, when it can be had
#   tools/setup.sh pictures   also the host's Xvfb, required (make shots)
#   tools/setup.sh export     also Debian's Linux export templates (make export)
#
# Godot: $GODOT, or `godot` on PATH, when it reports 4.6 or newer; otherwise Debian's own
# build (sid) unpacked into a private prefix under the cache folder and patched to use its
# own loader and libraries, sid's Mesa included (see tools/godot.sh for why). Everything
# downloaded is staged and only moved into place once it works, so an interrupted run never
# leaves a state the next run trusts.
# Writes build/tools.env (GODOT=..., GDLINT=..., GDFORMAT=...) for the Makefile.
set -euo pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
CACHE=${BOARD_STUDIO_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/board-studio}
PREFIX=$CACHE/godot-4.6
GUT_VERSION=9.6.0
GDTOOLKIT_VERSION=4.5.0
# sid's Mesa for the prefix's Godot: GLX and EGL through glvnd, llvmpipe and the hardware
# drivers (all inside libgallium since Mesa 24.2). Bump GL_STACK_MARK when this changes.
MESA_PACKAGES=(libgl1-mesa-dri libgl1 libegl1 libglx-mesa0 libegl-mesa0 libglvnd0 libglx0
	libgbm1 libllvm22 libdrm2 libdrm-common libdrm-amdgpu1 libdrm-intel1 libvulkan1 libxcb-glx0
	libxxf86vm1)
GL_STACK_MARK=.gl-stack-1
WANT=${1:-base}

say() { printf 'setup: %s\n' "$*" >&2; }
die() { printf '\nsetup failed: %s\n\n' "$*" >&2; exit 1; }

version_ok() { # "4.6.3.stable..." -> true when major.minor >= 4.6
	local v=$1 major minor
	major=${v%%.*}; minor=${v#*.}; minor=${minor%%.*}
	[[ $major =~ ^[0-9]+$ && $minor =~ ^[0-9]+$ ]] || return 1
	((major > 4 || (major == 4 && minor >= 6)))
}

host_has() { # command-or-file
	command -v "$1" >/dev/null 2>&1 || [ -e "$1" ]
}

can_apt() {
	[ "$(id -u)" = 0 ] && command -v apt-get >/dev/null
}

need_host_package() { # command-or-file package
	host_has "$1" && return 0
	if can_apt; then
		say "installing host package $2"
		apt-get update -qq >/dev/null 2>&1 || true
		DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "$2" >/dev/null ||
			die "apt-get could not install '$2'. Install it yourself (apt-get install $2) and run 'make setup' again."
	else
		die "the host program '$1' is missing. Install the Debian package '$2' (sudo apt-get install $2), then run 'make setup' again."
	fi
}

# The windowed checks need Xvfb, and Xvfb's GLX needs the host's own swrast driver.
XVFB_NEEDS=(xvfb-run xvfb /usr/lib/x86_64-linux-gnu/dri/swrast_dri.so libgl1-mesa-dri)

need_xvfb() {
	need_host_package "${XVFB_NEEDS[0]}" "${XVFB_NEEDS[1]}"
	need_host_package "${XVFB_NEEDS[2]}" "${XVFB_NEEDS[3]}"
}

want_xvfb() { # like need_xvfb, but only says so when it cannot install them (not root)
	if host_has "${XVFB_NEEDS[0]}" && host_has "${XVFB_NEEDS[2]}"; then return 0; fi
	if can_apt; then need_xvfb; return 0; fi
	say "no Xvfb here and no root to install it: make test will SKIP the windowed play check"
	say "(to run it: sudo apt-get install ${XVFB_NEEDS[1]} ${XVFB_NEEDS[3]})"
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

# A library's own RUNPATH hides the binary's forced RPATH from that library's dependencies:
# sid's libLLVM ($ORIGIN/../lib) then misses libxml2.so.16 and Mesa cannot load, and
# libpulse's points at the host's pulseaudio folder. Pin them to the prefix (a forced RPATH
# also reaches what they load), so no process needs LD_LIBRARY_PATH, which children inherit.
# Each file is patched as a copy and renamed: a running Godot keeps the old file mapped.
pin_library_paths() { # folder-to-scan final-lib-dir
	local f path want="$2:$2/pulseaudio"
	while IFS= read -r -d '' f; do
		path=$(patchelf --print-rpath "$f" 2>/dev/null) || continue
		case $path in '' | '$ORIGIN' | "$want") continue ;; esac
		cp -p "$f" "$f.pin" && patchelf --force-rpath --set-rpath "$want" "$f.pin" &&
			mv "$f.pin" "$f" || { rm -f "$f.pin"; die "patchelf could not patch $f."; }
	done < <(find "$1" -type f -name '*.so*' -print0)
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
	pin_library_paths "$stage/root/usr/lib/x86_64-linux-gnu" "$lib"
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
	# unlink before copying: overwriting in place would corrupt a running Godot's libraries
	cp -a --remove-destination "$stage/root/." "$PREFIX/root/"
	rm -rf "$stage"
	touch "$PREFIX/.extra-$name"
}

# Mesa from the same archive as the binary, patched like it. Also repairs a prefix whose
# Mesa an older setup unpacked without pinning libLLVM (the `make play` crash after
# `make shots`): the marker changed, so this runs once more there.
install_gl_stack() {
	[ -f "$PREFIX/$GL_STACK_MARK" ] && return 0
	# several checkouts share the cache: one setup does this while the others wait
	(
		flock 9
		[ -f "$PREFIX/$GL_STACK_MARK" ] || install_gl_stack_now
	) 9>"$PREFIX.gl-lock"
}

install_gl_stack_now() {
	local lib=$PREFIX/root/usr/lib/x86_64-linux-gnu
	need_host_package patchelf patchelf
	install_extra mesa "${MESA_PACKAGES[@]}"
	say "pinning the prefix's libraries to the prefix (GL stack)"
	pin_library_paths "$lib" "$lib"
	local name missing
	for name in libGL.so.1 libEGL.so.1 libGLX_mesa.so.0 libEGL_mesa.so.0; do
		missing=$("$lib/ld-linux-x86-64.so.2" --library-path "$lib:$lib/pulseaudio" \
			--list "$lib/$name" 2>&1 | grep -E 'not found|=> /(usr/)?lib/' || true)
		[ -z "$missing" ] || die "sid's Mesa in $PREFIX needs libraries the prefix lacks" \
			"($name: $(echo "$missing" | head -n 3 | tr -s '\n\t ' ' ')). Remove $PREFIX" \
			"and run 'make setup' again to fetch a consistent set."
	done
	touch "$PREFIX/$GL_STACK_MARK"
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
	case $WANT in base | test | pictures | export) ;;
	*) die "unknown setup part '$WANT' (use: base, test, pictures or export)." ;;
	esac
	godot=$(find_godot)
	# a Godot of your own uses your own GL; ours always gets the Mesa it was built with
	[ "$godot" != "$PREFIX/godot" ] || install_gl_stack
	case $WANT in
	base) ;;
	test) want_xvfb ;;
	pictures) need_xvfb ;;
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
	} >"$ROOT/build/tools.env.$$" # one per process: parallel setups never share a half file
	mv "$ROOT/build/tools.env.$$" "$ROOT/build/tools.env"
	import_project "$godot"
}

main
