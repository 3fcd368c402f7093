#!/usr/bin/env python3
"""Copies the licence notice of Godot and of every bundled library into a release folder.

Each library in LIB_DIR is matched to the Debian package that ships it (Debian names a
library package after the library's soname: libfoo.so.3 is in libfoo3, libfoo-1.so.0 in
libfoo-1-0; a few exceptions are listed below), and that package's
/usr/share/doc/<package>/copyright in SYSROOT is copied to OUT_DIR/<package>.txt. Godot's is
OUT_DIR/godot.txt. OUT_DIR/INDEX.txt says which file covers which library. A library with no
copyright file found is an error (exit 1), so nothing ships without its notice.

Usage: licences.py SYSROOT LIB_DIR OUT_DIR
"""

import os
import re
import shutil
import sys

# libraries whose package is not named after them
EXCEPTIONS = {
    "ld-linux-x86-64": "libc6",
    "libm": "libc6",
    "libmvec": "libc6",
    "libGLdispatch": "libglvnd0",
    "libz": "zlib1g",
    "libpulsecommon": "libpulse0",
    "libgallium": "mesa-libgallium",
    "libbrotlicommon": "libbrotli1",
    "libbrotlidec": "libbrotli1",
    "libicudata": "libicu78",
    "libicuuc": "libicu78",
    "libicui18n": "libicu78",
}


def _plain(name):
    return re.sub(r"[^a-z0-9]", "", name.lower())


def split_soname(file_name):
    """'libfoo-1.2.so.3.4' -> ('libfoo-1.2', '3'); 'libgallium-26.2.6-1.so' -> ('libgallium', '')."""
    base, _, version = file_name.partition(".so")
    version = version.lstrip(".").split(".")[0]
    if base.startswith("libgallium-") or base.startswith("libpulsecommon-"):
        base = base.split("-")[0]
    return base, version


def package_of(file_name, packages):
    """The Debian package (a name in packages) that ships the library file_name, or None."""
    base, version = split_soname(file_name)
    if base in EXCEPTIONS:
        return EXCEPTIONS[base] if EXCEPTIONS[base] in packages else None
    want = _plain(base[3:] if base.startswith("lib") else base)
    found = []
    for package in packages:
        name = package[:-3] if package.endswith("t64") else package
        plain = _plain(name[3:] if name.startswith("lib") else name)
        rest = plain[len(want):]
        if plain.startswith(want) and re.fullmatch(r"(\d[a-z0-9]*)?", rest):
            found.append((not rest.startswith(version) if version else False, len(plain), package))
    return min(found)[2] if found else None


def main(argv):
    if len(argv) != 3:
        print("usage: licences.py SYSROOT LIB_DIR OUT_DIR", file=sys.stderr)
        return 2
    sysroot, lib_dir, out_dir = argv
    doc = os.path.join(sysroot, "usr/share/doc")
    packages = sorted(p for p in os.listdir(doc) if os.path.isfile(os.path.join(doc, p, "copyright")))
    os.makedirs(out_dir, exist_ok=True)
    shutil.copyfile(os.path.join(doc, "godot-template-release", "copyright"), os.path.join(out_dir, "godot.txt"))
    index = ["Board Studio runs on the Godot Engine: its licence is godot.txt.", "",
             "Each bundled library and the file with its licence notice (its Debian copyright file):", ""]
    missing = []
    for root, _dirs, files in os.walk(lib_dir):
        for file_name in sorted(files):
            if ".so" not in file_name or os.path.islink(os.path.join(root, file_name)):
                continue
            package = package_of(file_name, packages)
            shown = os.path.relpath(os.path.join(root, file_name), lib_dir)
            if package is None:
                missing.append(shown)
                continue
            target = os.path.join(out_dir, package + ".txt")
            if not os.path.exists(target):
                shutil.copyfile(os.path.join(doc, package, "copyright"), target)
            index.append("  %-40s %s.txt" % (shown, package))
    for shown in missing:
        print("licences: no Debian copyright file found for %s" % shown, file=sys.stderr)
    with open(os.path.join(out_dir, "INDEX.txt"), "w", encoding="utf-8") as handle:
        handle.write("\n".join(index) + "\n")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
