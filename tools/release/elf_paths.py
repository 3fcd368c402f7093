#!/usr/bin/env python3
"""Checks that no ELF file in a release folder names a path outside that folder.

For every ELF file (found by its magic bytes, whatever its name) it reads:
  - the interpreter (PT_INTERP): must be relative, with no "..";
  - RPATH / RUNPATH: must be empty, or only $ORIGIN-relative entries that stay inside;
  - NEEDED: plain library names, never a path;
and it looks through the whole file for each --forbid string (this machine's build paths).
Prints one line per problem and exits 1 when there is any; prints a summary line otherwise.

Usage: elf_paths.py [--forbid PATH]... FOLDER
"""

import os
import struct
import sys

PT_INTERP = 3
PT_DYNAMIC = 2
DT_NULL, DT_NEEDED, DT_STRTAB, DT_RPATH, DT_RUNPATH = 0, 1, 5, 15, 29


class ElfInfo:
    """The dynamic-linking names of one ELF file."""

    def __init__(self):
        self.interpreter = None
        self.needed = []
        self.search_paths = []


def _vaddr_to_offset(segments, vaddr):
    for p_type, offset, p_vaddr, filesz in segments:
        if p_type == 1 and p_vaddr <= vaddr < p_vaddr + filesz:  # PT_LOAD
            return offset + (vaddr - p_vaddr)
    return None


def _c_string(data, offset):
    end = data.find(b"\0", offset)
    return data[offset:end].decode("utf-8", "replace")


def read_elf(data):
    """Returns ElfInfo for a 64-bit little-endian ELF image, or raises ValueError."""
    if data[:4] != b"\x7fELF" or data[4] != 2 or data[5] != 1:
        raise ValueError("not a 64-bit little-endian ELF file")
    phoff, = struct.unpack_from("<Q", data, 0x20)
    phentsize, phnum = struct.unpack_from("<HH", data, 0x36)
    segments = []
    info = ElfInfo()
    dynamic = None
    for i in range(phnum):
        base = phoff + i * phentsize
        p_type, _flags, offset, vaddr, _paddr, filesz = struct.unpack_from("<IIQQQQ", data, base)
        segments.append((p_type, offset, vaddr, filesz))
        if p_type == PT_INTERP:
            info.interpreter = data[offset:offset + filesz].rstrip(b"\0").decode("utf-8", "replace")
        elif p_type == PT_DYNAMIC:
            dynamic = (offset, filesz)
    if dynamic is None:
        return info
    entries = []
    strtab = None
    for pos in range(dynamic[0], dynamic[0] + dynamic[1], 16):
        tag, value = struct.unpack_from("<qQ", data, pos)
        if tag == DT_NULL:
            break
        if tag == DT_STRTAB:
            strtab = _vaddr_to_offset(segments, value)
        entries.append((tag, value))
    if strtab is None:
        raise ValueError("dynamic section without a string table")
    for tag, value in entries:
        if tag == DT_NEEDED:
            info.needed.append(_c_string(data, strtab + value))
        elif tag in (DT_RPATH, DT_RUNPATH):
            info.search_paths.extend(_c_string(data, strtab + value).split(":"))
    return info


def problems_of(path, folder, forbidden):
    """Every way the file at path names something outside folder."""
    with open(path, "rb") as handle:
        data = handle.read()
    if data[:4] != b"\x7fELF":
        return []
    name = os.path.relpath(path, folder)
    try:
        info = read_elf(data)
    except (ValueError, struct.error) as error:
        return ["%s: unreadable ELF (%s)" % (name, error)]
    found = []
    if info.interpreter and (info.interpreter.startswith("/") or ".." in info.interpreter):
        found.append("%s: interpreter %s" % (name, info.interpreter))
    for entry in info.search_paths:
        if not entry:
            continue
        resolved = os.path.normpath(entry.replace("$ORIGIN", os.path.dirname(path)))
        if not entry.startswith("$ORIGIN") or not resolved.startswith(os.path.abspath(folder)):
            found.append("%s: library search path %s" % (name, entry))
    for needed in info.needed:
        if "/" in needed:
            found.append("%s: needs a library by path %s" % (name, needed))
    for text in forbidden:
        if text.encode() in data:
            found.append("%s: contains the build path %s" % (name, text))
    return found


def main(argv):
    forbidden = []
    args = list(argv)
    while args and args[0] == "--forbid":
        forbidden.append(args[1].rstrip("/"))
        args = args[2:]
    if len(args) != 1 or not os.path.isdir(args[0]):
        print("usage: elf_paths.py [--forbid PATH]... FOLDER", file=sys.stderr)
        return 2
    folder = os.path.abspath(args[0])
    elf_count = 0
    problems = []
    for base, _dirs, files in os.walk(folder):
        for file_name in sorted(files):
            path = os.path.join(base, file_name)
            if os.path.islink(path) or not os.path.isfile(path):
                continue
            with open(path, "rb") as handle:
                is_elf = handle.read(4) == b"\x7fELF"
            if is_elf:
                elf_count += 1
                problems.extend(problems_of(path, folder, forbidden))
    for line in problems:
        print("elf-paths: " + line)
    if elf_count == 0:
        print("elf-paths: no ELF file in %s" % folder)
        return 1
    if problems:
        return 1
    print("elf-paths: %d ELF files, none names a path outside the folder" % elf_count)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
