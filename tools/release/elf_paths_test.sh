#!/usr/bin/env bash
# Tests of tools/release/elf_paths.py (the release check's "no ELF names a path outside the
# folder") on copies of a system program patched with patchelf: each way a file can name a
# path outside its folder must be caught, and a clean folder must pass. Exit 1 on a failure.
set -uo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
command -v patchelf >/dev/null || { echo "elf-paths test: SKIPPED: no patchelf"; exit 0; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failed=0
expect() { # name want-status want-text folder [--forbid X]
	local name=$1 want=$2 text=$3; shift 3
	out=$(python3 "$HERE/elf_paths.py" "$@" 2>&1)
	status=$?
	if [ "$status" = "$want" ] && [[ $out == *"$text"* ]]; then
		echo "elf-paths test: ok: $name"
	else
		echo "elf-paths test: FAILED: $name (exit $status: $out)"
		failed=1
	fi
}
fresh() { # a folder with one copy of /bin/true, its interpreter made relative
	rm -rf "$tmp/f"; mkdir -p "$tmp/f/lib"
	cp /bin/true "$tmp/f/prog"
	patchelf --set-interpreter lib/ld-linux-x86-64.so.2 "$tmp/f/prog"
}

fresh
expect "a folder whose ELF names nothing outside passes" 0 "1 ELF files, none names" "$tmp/f"
cp /bin/true "$tmp/f/prog"
expect "an absolute interpreter is caught" 1 "prog: interpreter /lib64/ld-linux-x86-64.so.2" "$tmp/f"
fresh
patchelf --set-rpath /opt/somewhere "$tmp/f/prog"
expect "an absolute library search path is caught" 1 "prog: library search path /opt/somewhere" "$tmp/f"
fresh
patchelf --set-rpath '$ORIGIN/../../outside' "$tmp/f/prog"
expect "an \$ORIGIN path that leaves the folder is caught" 1 "library search path \$ORIGIN/../../outside" "$tmp/f"
fresh
patchelf --set-rpath '$ORIGIN/lib' "$tmp/f/prog"
expect "an \$ORIGIN path inside the folder passes" 0 "none names" "$tmp/f"
fresh
patchelf --add-needed /usr/lib/libfoo.so.1 "$tmp/f/prog"
expect "a library needed by its path is caught" 1 "needs a library by path /usr/lib/libfoo.so.1" "$tmp/f"
fresh
printf '/build/machine/prefix' >>"$tmp/f/prog"
expect "a build path anywhere in the file is caught" 1 "contains the build path /build/machine/prefix" \
	--forbid /build/machine/prefix "$tmp/f"
rm -rf "$tmp/f"; mkdir -p "$tmp/f"; echo text >"$tmp/f/readme"
expect "a folder with no ELF at all fails (nothing was checked)" 1 "no ELF file" "$tmp/f"
exit $failed
