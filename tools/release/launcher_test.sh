#!/usr/bin/env bash
# Tests of the release launcher's error paths (tools/release/files/board-studio), on a small
# stand-in folder: the real launcher and MANIFEST, with a fake loader in place of the engine
# that prints what it was given and exits, crashes or fails as the test asks. Needs no
# release build, so make test always runs it. Prints "launcher: ok ..." / "FAILED ..." per
# case and exits 1 when any failed.
set -uo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
HERE=$ROOT/tools/release
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failed=0
check() { # name condition-status detail
	if [ "$2" = 0 ]; then echo "launcher: ok: $1"; else echo "launcher: FAILED: $1 ($3)"; failed=1; fi
}

# A stand-in game folder: FAKE=crash crashes (SIGSEGV), FAKE=crash-hw crashes unless the
# software renderer was asked for, FAKE=fail exits 1; otherwise it prints its arguments.
make_folder() {
	local folder="$tmp/my games/board studio" # spaces: players unpack anywhere
	rm -rf "$folder"
	mkdir -p "$folder/engine/lib"
	cp "$HERE/files/board-studio" "$folder/board-studio"
	cat >"$folder/engine/board-studio" <<'EOF'
#!/bin/sh
case ${FAKE:-} in
crash) kill -SEGV $$ ;;
crash-hw) [ -n "${LIBGL_ALWAYS_SOFTWARE:-}" ] || kill -SEGV $$ ;;
fail) exit 1 ;;
esac
echo "args: $*"
echo "software: ${LIBGL_ALWAYS_SOFTWARE:-no} ${__GLX_VENDOR_LIBRARY_NAME:-any}"
echo "alsa: ${ALSA_CONFIG_PATH:-system}"
EOF
	chmod 755 "$folder/board-studio" "$folder/engine/board-studio"
	echo "engine" >"$folder/engine/godot"
	echo "pack" >"$folder/engine/board-studio.pck"
	echo "lib" >"$folder/engine/lib/libz.so.1"
	"$HERE/manifest.sh" "$folder"
	echo "$folder"
}

run() { # env-assignments... -- launcher-args... : sets out, err, status
	local envs=()
	while [ "$1" != -- ]; do envs+=("$1"); shift; done
	shift
	env -i PATH="$PATH" "${envs[@]}" "$game/board-studio" "$@" >"$tmp/out" 2>"$tmp/err"
	status=$?
	out=$(cat "$tmp/out")
	err=$(cat "$tmp/err")
}

game=$(make_folder)
run -- --headless -- --autoplay=maze --seed=2
[ "$status" = 0 ] && [[ $out == *"args: --library-path $game/engine/lib --argv0 $game/board-studio $game/engine/godot --headless -- --autoplay=maze --seed=2"* ]] && [ -z "$err" ]
check "a whole folder starts the engine through the loader with the player's options unchanged" $? "status $status, out '$out', err '$err'"

ln -s "$game/board-studio" "$tmp/start-link"
env -i PATH="$PATH" "$tmp/start-link" --headless >"$tmp/out" 2>&1
grep -q "args: --library-path $game/engine/lib" "$tmp/out"
check "started through a symbolic link, it still finds its folder" $? "$(cat "$tmp/out")"

rm "$game/engine/godot"
run -- --headless
[ "$status" = 1 ] && [[ $err == "Board Studio: cannot start: the file engine/godot is missing from its folder ($game)."* ]] && [ -z "$out" ]
check "a missing file is named and the engine is not started" $? "status $status, err '$err'"

game=$(make_folder)
rm "$game/engine/lib/libz.so.1"
run -- --headless
[ "$status" = 1 ] && [[ $err == *"the file engine/lib/libz.so.1 is missing"* ]]
check "a missing library is named" $? "status $status, err '$err'"

game=$(make_folder)
echo "more" >>"$game/engine/board-studio.pck"
run -- --headless
[ "$status" = 1 ] && [[ $err == *"the file engine/board-studio.pck in its folder ($game) is damaged (its size is wrong)."* ]] && [ -z "$out" ]
check "a file of the wrong size is named before the start" $? "status $status, err '$err'"

game=$(make_folder)
printf 'PACK' | dd of="$game/engine/board-studio.pck" bs=1 seek=0 conv=notrunc 2>/dev/null
run FAKE=fail -- --headless
[ "$status" = 1 ] && [[ $err == *"stopped because the file engine/board-studio.pck in its folder ($game) is damaged (it differs from the download)."* ]]
check "after a failed run, a file with the right size but other contents is named" $? "status $status, err '$err'"

game=$(make_folder)
run FAKE=fail -- --headless
[ "$status" = 1 ] && [ -z "$err" ]
check "a game that exits with an error of its own gets no extra words" $? "status $status, err '$err'"

chmod -x "$game/engine/board-studio"
run -- --headless
[ "$status" = 126 ] && [[ $err == *"the system refused to run the engine in its folder ($game)"* ]]
check "a folder where programs may not run (noexec) is said in one sentence" $? "status $status, err '$err'"
chmod +x "$game/engine/board-studio"

rm "$game/MANIFEST"
run -- --headless
[ "$status" = 1 ] && [[ $err == *"the file MANIFEST is missing from its folder ($game)."* ]]
check "a missing MANIFEST is named" $? "status $status, err '$err'"

game=$(make_folder)
run -- --autoplay=maze
[ "$status" = 1 ] && [[ $err == *"needs a desktop session (X11 or Wayland)"*"./board-studio --headless -- --autoplay=maze"* ]] && [ -z "$out" ]
check "no display: one sentence saying what is missing and what works without it" $? "status $status, err '$err'"

run -- --headless -- --help
[ "$status" = 0 ]
check "no display is fine for --headless" $? "status $status, err '$err'"

run DISPLAY=:99 FAKE=crash-hw --
[ "$status" = 0 ] && [[ $err == *"starting again with Mesa's software renderer"* ]] && [[ $out == *"software: 1 mesa"* ]]
check "a crash at the start of a window retries once with the software renderer" $? "status $status, out '$out', err '$err'"

run DISPLAY=:99 FAKE=crash --
[ "$status" = 139 ] && [[ $err == *"stopped unexpectedly (signal 11)"* ]] && [ "$(grep -c 'starting again' "$tmp/err")" = 1 ]
check "a crash that stays is one sentence after one retry, never a loop" $? "status $status, err '$err'"

run DISPLAY=:99 BOARD_STUDIO_SOFTWARE_GL=1 --
[ "$status" = 0 ] && [[ $out == *"software: 1 mesa"* ]]
check "BOARD_STUDIO_SOFTWARE_GL=1 asks Mesa for the software renderer" $? "status $status, out '$out'"

run PULSE_SERVER=unix:/tmp/some-server -- --headless
if [ -f /usr/share/alsa/alsa.conf ]; then
	[[ $out == *"alsa: system"* ]]
else
	[[ $out == *"alsa: $game/engine/share/alsa/alsa.conf"* ]]
fi
check "with a sound server, ALSA keeps the system's config where there is one" $? "out '$out'"

run XDG_RUNTIME_DIR="$tmp/no-such-dir" -- --headless
if ls /dev/snd/pcmC* >/dev/null 2>&1; then
	[[ $out == *"alsa: "* ]] # a sound card here: either is right
else
	[[ $out == *"alsa: $game/engine/share/alsa/alsa.conf"* ]]
fi
check "with no sound card and no sound server, ALSA gets the folder's silent config" $? "out '$out'"

exit $failed
