#!/usr/bin/env bash
# make release-check: the release archive (make release) on a clean Debian 12 with no Godot
# and no project, as a player's machine would have it:
#   (a) both headless autoplays run from the unpacked folder inside a debootstrapped bookworm
#       root, and their JSON equals the build tree's game (same seed, same state hash);
#   (b) the window opens there under Xvfb for 15 s: screenshot build/release-check/menu.png;
#       then the keyboard (xdotool) opens Tilt Maze's first board: maze.png, the 3D board
#       drawn by the folder's Mesa; every library the running game has mapped comes from the
#       folder, and it printed none of the warnings a player should not see (fontconfig,
#       XKB, ALSA, GL loader);
#   (c) no ELF in the folder names a path outside it (tools/release/elf_paths.py);
#   (d) a missing and a damaged file each get the launcher's one sentence naming the file;
#   (e) the GUT suites (the test pack of tools/release_tests.sh) on the folder's own engine
#       and libraries inside the root.
# Prints SKIPPED with the reason and exits 77 when this machine cannot do it (no root, no
# debootstrap, no Debian archive, no Xvfb). Exits 1 when a check fails.
set -uo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
cd "$ROOT" || exit 1
HERE=tools/release
REPORT=build/release-check
skip() { echo "release-check: SKIPPED: $*"; exit 77; }
failed=0
fail() { echo "release-check: FAILED: $*"; failed=1; }
ok() { echo "release-check: ok: $*"; }

archive=$(ls build/release/board-studio-*-linux-x86_64.tar.gz 2>/dev/null | head -n 1)
[ -n "$archive" ] || { echo "release-check: no archive in build/release/: run 'make release' first." >&2; exit 1; }
[ "$(id -u)" = 0 ] || skip "entering a Debian 12 root (chroot) needs root"
command -v unshare >/dev/null || skip "no unshare (util-linux) to give the root its own mounts"
reason=$(mktemp)
rootfs=$("$HERE/bookworm_root.sh" 2>"$reason") || { r=$(tail -n 1 "$reason"); rm -f "$reason"; skip "$r"; }
rm -f "$reason"

# a check that was killed (no EXIT trap ran) leaves its scratch folder: drop those whose
# process is gone, and never count another running check's folder as part of the root
for stale in "$rootfs"/tmp/release-check.*; do
	[ -d "$stale" ] || continue
	kill -0 "${stale##*.}" 2>/dev/null || rm -rf "$stale"
done
# the root must be clean: no Godot, no project, no X or GL libraries of its own
leftover=$(find "$rootfs" -xdev -path "$rootfs/tmp/release-check.*" -prune -o \( -iname '*godot*' -o -name project.godot -o -name 'libX11.so*' \
	-o -name 'libGL*.so*' -o -name 'libasound.so*' \) -print -quit 2>/dev/null)
[ -z "$leftover" ] || { echo "release-check: the Debian 12 root is not clean ($leftover); remove $rootfs* to remake it." >&2; exit 1; }

rm -rf "$REPORT"
mkdir -p "$REPORT"
work=/tmp/release-check.$$ # inside the root
scratch=$rootfs$work
xvfb_pid=
cleanup() {
	[ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null
	rm -rf "$scratch"
}
trap cleanup EXIT
mkdir -p "$scratch/home"
tar -C "$scratch" -xzf "$archive" || { echo "release-check: could not unpack $archive" >&2; exit 1; }
folder_name=$(basename "$archive" -linux-x86_64.tar.gz)
[ -x "$scratch/$folder_name/board-studio" ] || { fail "the archive does not unpack to $folder_name/board-studio"; exit 1; }
game=$work/$folder_name

# Runs a command inside the root as a player would: own mounts (gone when it ends), a clean
# environment, HOME in the scratch folder.
in_root() { # display command...
	local display=$1; shift
	unshare -m --propagation private sh -c '
		root=$1; shift
		mount -t proc proc "$root/proc" && mount --bind /dev "$root/dev" &&
			mkdir -p "$root/tmp/.X11-unix" && mount --bind /tmp/.X11-unix "$root/tmp/.X11-unix" &&
			exec chroot "$root" "$@"' sh "$rootfs" \
		env -i PATH=/usr/bin:/bin HOME="$work/home" LANG=C.UTF-8 ${display:+DISPLAY=$display} "$@"
}

# (c) paths
if python3 "$HERE/elf_paths.py" --forbid "$ROOT" --forbid "${BOARD_STUDIO_CACHE:-$HOME/.cache/board-studio}/godot-4.6" \
	"$scratch/$folder_name"; then ok "no ELF names a path outside the folder"; else fail "an ELF names a path outside the folder (above)"; fi

# (a) the autoplays: the release in the root against the build tree's game
for spec in "pachinko 60" "maze 60"; do
	set -- $spec
	flags=(--autoplay="$1" --seed=1 --seconds="$2")
	tree=$(timeout 300 tools/godot.sh --headless --path . -- "${flags[@]}" 2>/dev/null | grep -E '^\{' | tail -n 1)
	started=$(date +%s)
	released=$(in_root '' timeout 300 "$game/board-studio" --headless -- "${flags[@]}" \
		2>"$REPORT/autoplay-$1.err" | grep -E '^\{' | tail -n 1)
	took=$(($(date +%s) - started))
	if verdict=$(python3 "$HERE/same_report.py" "$tree" "$released" 2>&1); then
		ok "$1 autoplay in the Debian 12 root equals the build tree's ($verdict, ${took} s)"
	else
		fail "$1 autoplay differs from the build tree's: $verdict"
		tail -n 5 "$REPORT/autoplay-$1.err"
	fi
done

# (b) the window under Xvfb
have_x_tools() {
	command -v Xvfb >/dev/null && command -v xwd >/dev/null && command -v xwdtopnm >/dev/null &&
		command -v xdotool >/dev/null
}
if ! have_x_tools && command -v apt-get >/dev/null; then
	DEBIAN_FRONTEND=noninteractive apt-get install -y -qq xvfb x11-apps netpbm xdotool >/dev/null 2>&1 || true
fi
# Mean brightness (0-255) above which the screen shows the light wooden maze board: the dark
# menus measure about 30, a maze board in its window about 125 (black screen border included).
LIGHT_BOARD=90
shoot() { # display name: the whole screen as build/release-check/NAME.png; prints its brightness
	xwd -root -display "$1" 2>/dev/null | xwdtopnm 2>/dev/null >"$REPORT/$2.ppm"
	pnmtopng <"$REPORT/$2.ppm" >"$REPORT/$2.png" 2>/dev/null
	python3 "$HERE/mean_brightness.py" "$REPORT/$2.ppm" 2>/dev/null || echo 0
	rm -f "$REPORT/$2.ppm"
}
if ! have_x_tools; then
	echo "release-check: SKIPPED the window part: no Xvfb, xwd, netpbm or xdotool here (apt-get install xvfb x11-apps netpbm xdotool)"
else
	n=90
	while [ -e "/tmp/.X11-unix/X$n" ] || [ -e "/tmp/.X$n-lock" ]; do n=$((n + 1)); done
	Xvfb ":$n" -screen 0 1280x720x24 -nolisten tcp -ac >/dev/null 2>&1 &
	xvfb_pid=$!
	for _ in $(seq 50); do [ -e "/tmp/.X11-unix/X$n" ] && break; sleep 0.1; done
	(in_root ":$n" "$game/board-studio") >"$REPORT/window.log" 2>&1 &
	game_pid=$!
	sleep 15
	engine=$(pgrep -f "^$game/engine/board-studio --library-path" | head -n 1)
	menu_light=$(shoot ":$n" menu)
	# Tilt Maze (third button, under Play Pachinko and Pachinko boards), then its first board
	# once the level select has loaded it:
	# Enter until the light maze board fills the screen (the menus are dark), 40 s at most.
	maze_light=0
	window=$(DISPLAY=":$n" xdotool search --name "Board Studio" 2>/dev/null | head -n 1)
	if [ -n "$window" ]; then
		DISPLAY=":$n" xdotool windowfocus "$window" key Down sleep 0.3 key Down sleep 0.5 key Return
		for _ in $(seq 20); do
			sleep 2
			maze_light=$(shoot ":$n" maze)
			[ "$maze_light" -gt "$LIGHT_BOARD" ] && break
			DISPLAY=":$n" xdotool windowfocus "$window" key Return
		done
		sleep 3 # the balls roll in after the board appears
		maze_light=$(shoot ":$n" maze)
	fi
	outside=
	if [ -n "$engine" ]; then
		outside=$(awk '$6 ~ /\.so/ { print $6 }' "/proc/$engine/maps" | sort -u | grep -v "^$scratch/$folder_name/" || true)
		mapped=$(awk '$6 ~ /\.so/ { print $6 }' "/proc/$engine/maps" | sort -u | wc -l)
	fi
	pkill -TERM -P "$game_pid" 2>/dev/null
	[ -n "$engine" ] && kill "$engine" 2>/dev/null
	wait "$game_pid" 2>/dev/null
	kill "$xvfb_pid" 2>/dev/null; wait "$xvfb_pid" 2>/dev/null; xvfb_pid=
	if [ -z "$engine" ]; then
		fail "the game was not running after 15 s in the window (log: $REPORT/window.log)"
		tail -n 8 "$REPORT/window.log"
	elif [ -n "$outside" ]; then
		fail "the running game mapped libraries from outside its folder: $(echo $outside)"
	else
		ok "the window ran 15 s; all $mapped libraries it mapped are the folder's"
	fi
	if [ -s "$REPORT/menu.png" ] && [ "$menu_light" -gt 8 ]; then
		ok "the main menu drew (brightness $menu_light; screenshot $REPORT/menu.png)"
	else
		fail "the window drew nothing at the main menu ($REPORT/menu.png)"
	fi
	if [ "$maze_light" -gt "$LIGHT_BOARD" ]; then
		ok "the maze board drew in 3D (brightness $maze_light; screenshot $REPORT/maze.png)"
	else
		fail "the maze board never showed (last screenshot $REPORT/maze.png)"
	fi
	noise=$(grep -iE 'fontconfig|xkbcommon|compose|ALSA lib|MESA-LOADER|libEGL warning|glx: failed|cannot open shared|not found' \
		"$REPORT/window.log" | head -n 5)
	if [ -n "$noise" ]; then fail "the window printed warnings a player should not see: $noise"; else ok "no fontconfig, XKB, ALSA or GL loader warnings"; fi
fi

# (e) the GUT suites on the folder's own engine and libraries, inside the root: the test
# pack (tools/release_tests.sh --pack) beside a copy of the folder's loader named "tests",
# so the release template loads tests.pck as it loads the game's pack
packed=$(mktemp -d)
if tools/release_tests.sh --pack "$packed" >"$REPORT/test-pack.log" 2>&1; then
	engine_dir=$scratch/$folder_name/engine
	cp "$packed/tests.pck" "$packed/fixtures.pck" "$engine_dir/"
	cp "$engine_dir/board-studio" "$engine_dir/tests"
	started=$(date +%s)
	in_root '' timeout 1800 "$game/engine/tests" --library-path "$game/engine/lib" \
		"$game/engine/godot" --headless -gtest="$(paste -sd, "$packed/tests.list")" \
		-gjunit_xml_file="$work/release-tests.xml" -glog=1 -gexit >"$REPORT/release-tests.log" 2>&1
	cp "$scratch/release-tests.xml" "$REPORT/release-tests.xml" 2>/dev/null
	read -r passed_in_root failed_in_root < <(python3 tools/junit_counts.py "$REPORT/release-tests.xml")
	if [ "$passed_in_root" -gt 0 ] && [ "$failed_in_root" = 0 ]; then
		ok "the GUT suites on the folder's engine in the Debian 12 root: $passed_in_root passed ($(($(date +%s) - started)) s)"
	else
		fail "the GUT suites in the Debian 12 root: $passed_in_root passed, $failed_in_root failed (log: $REPORT/release-tests.log)"
	fi
	rm -f "$engine_dir/tests" "$engine_dir/tests.pck" "$engine_dir/fixtures.pck"
else
	fail "the test pack could not be made (log: $REPORT/test-pack.log)"
fi
rm -rf "$packed"

# (d) a missing and a damaged file, each named in one sentence
victim=engine/lib/libz.so.1
mv "$scratch/$folder_name/$victim" "$scratch/$folder_name/$victim.away"
said=$(in_root '' "$game/board-studio" --headless -- --autoplay=maze --seconds=1 2>&1 >/dev/null | tail -n 1)
mv "$scratch/$folder_name/$victim.away" "$scratch/$folder_name/$victim"
case $said in *"$victim is missing"*) ok "a missing file is named: $said" ;; *) fail "a missing $victim gave: $said" ;; esac
victim=engine/board-studio.pck
printf 'XXXX' | dd of="$scratch/$folder_name/$victim" bs=1 seek=0 conv=notrunc 2>/dev/null
said=$(in_root '' "$game/board-studio" --headless -- --autoplay=maze --seconds=1 2>&1 >/dev/null | tail -n 1)
case $said in *"$victim"*damaged*) ok "a damaged file is named: $said" ;; *) fail "a damaged $victim gave: $said" ;; esac

exit $failed
