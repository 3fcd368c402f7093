#!/usr/bin/env python3
"""Lists what a Godot 4 .pck holds, and fails when it holds what it must not.

    tools/pck_list.py build/export/board_studio.pck                 summary line only
    tools/pck_list.py --list build/export/board_studio.pck          every file and its size
    tools/pck_list.py --forbid 'tests/*' --forbid '*shot*' PCK      exit 1 if a path matches

Reads the pack header and directory as Godot 4 writes them (little endian):
  "GDPC", pack format version (u32), engine major, minor, patch (u32 each), flags (u32),
  file base (u64), directory offset (u64, format 3 and later only), 16 reserved u32s;
  at the directory: file count (u32), then per file: path length (u32, the path is
  zero-padded to it), path (UTF-8), offset from the file base (u64), size (u64), MD5 (16
  bytes), flags (u32). A pack embedded in an executable ends with its size (u64) and "GDPC".
Patterns are shell globs (fnmatch, where "*" also crosses "/") matched against the paths
as packed, without "res://": "tests/*" is everything under tests/.
Exit status: 0 fine, 1 a forbidden path, 2 the file could not be read as a pack.
"""

import argparse
import fnmatch
import re
import struct
import sys
from dataclasses import dataclass

MAGIC = b"GDPC"
FORMATS = (2, 3)
FLAG_DIR_ENCRYPTED = 1 << 0
FLAG_REL_FILEBASE = 1 << 1
FILE_FLAG_ENCRYPTED = 1 << 0
FILE_FLAG_REMOVAL = 1 << 1
CLASS_CACHE = ".godot/global_script_class_cache.cfg"


class PackError(Exception):
    """The file is not a pack this lister can read; the message says why."""


@dataclass
class Entry:
    path: str
    offset: int  # from the start of the file
    size: int
    flags: int


@dataclass
class Pack:
    format_version: int
    engine: str
    flags: int
    entries: list


class Reader:
    """Little-endian reads from a byte string that name what was cut short."""

    def __init__(self, data: bytes, position: int):
        self.data = data
        self.position = position

    def take(self, count: int, what: str) -> bytes:
        end = self.position + count
        if count < 0 or end > len(self.data):
            raise PackError("the file ends inside %s (at byte %d)" % (what, self.position))
        chunk = self.data[self.position : end]
        self.position = end
        return chunk

    def u32(self, what: str) -> int:
        return struct.unpack("<I", self.take(4, what))[0]

    def u64(self, what: str) -> int:
        return struct.unpack("<Q", self.take(8, what))[0]


def find_start(data: bytes) -> int:
    """Where the pack starts: a .pck at byte 0, an embedded one from its trailer."""
    if data[:4] == MAGIC:
        return 0
    if len(data) >= 12 and data[-4:] == MAGIC:
        size = struct.unpack("<Q", data[-12:-4])[0]
        start = len(data) - 12 - size
        if 0 <= start and data[start : start + 4] == MAGIC:
            return start
    raise PackError('no "GDPC" header at the start or in a trailer: not a Godot pack')


def read_pack(data: bytes) -> Pack:
    start = find_start(data)
    reader = Reader(data, start + 4)
    version = reader.u32("the pack format version")
    if version not in FORMATS:
        raise PackError("pack format %d is not one this lister reads %s" % (version, FORMATS))
    engine = "%d.%d.%d" % tuple(reader.u32("the engine version") for _ in range(3))
    flags = reader.u32("the pack flags")
    if flags & FLAG_DIR_ENCRYPTED:
        raise PackError("the directory is encrypted: its paths cannot be listed")
    file_base = reader.u64("the file base")
    directory = reader.u64("the directory offset") if version >= 3 else None
    reader.take(16 * 4, "the reserved header words")
    if flags & FLAG_REL_FILEBASE:
        file_base += start
    if directory is not None:
        reader.position = start + directory
    return Pack(version, engine, flags, read_directory(reader, file_base, len(data)))


def read_directory(reader: Reader, file_base: int, total: int) -> list:
    count = reader.u32("the file count")
    entries = []
    for index in range(count):
        what = "directory entry %d of %d" % (index + 1, count)
        length = reader.u32(what)
        raw = reader.take(length, what).rstrip(b"\0")
        try:
            path = raw.decode("utf-8")
        except UnicodeDecodeError as error:
            raise PackError("%s: the path is not UTF-8 (%s)" % (what, error)) from None
        offset = file_base + reader.u64(what)
        size = reader.u64(what)
        reader.take(16, what)  # MD5
        flags = reader.u32(what)
        if offset + size > total and not flags & FILE_FLAG_REMOVAL:
            raise PackError("%s: %s lies past the end of the file" % (what, path))
        entries.append(Entry(path.removeprefix("res://"), offset, size, flags))
    return entries


def dangling_classes(data: bytes, pack: Pack) -> list:
    """Scripts the packed class cache names that the pack does not hold (names only)."""
    cache = next((e for e in pack.entries if e.path == CLASS_CACHE), None)
    if cache is None or cache.flags & FILE_FLAG_ENCRYPTED:
        return []
    text = data[cache.offset : cache.offset + cache.size].decode("utf-8", "replace")
    held = {e.path for e in pack.entries}
    named = re.findall(r'"path": "res://([^"]+)"', text)
    # scripts are packed compiled (.gdc) or with a .remap beside them
    return [p for p in named if not {p, p + ".remap", p[:-3] + ".gdc"} & held]


def describe_flags(flags: int) -> str:
    names = []
    if flags & FLAG_REL_FILEBASE:
        names.append("relative file base")
    unknown = flags & ~(FLAG_DIR_ENCRYPTED | FLAG_REL_FILEBASE)
    if unknown:
        names.append("other bits 0x%x" % unknown)
    return ", ".join(names) or "none"


def main(argv: list) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("pack", help="a .pck file, or an executable with an embedded pack")
    parser.add_argument("--list", action="store_true", help="print every file and its size")
    parser.add_argument(
        "--forbid", action="append", default=[], metavar="GLOB", help="fail on a match"
    )
    args = parser.parse_args(argv)
    try:
        with open(args.pack, "rb") as stream:
            data = stream.read()
        pack = read_pack(data)
    except OSError as error:
        print("pck_list: cannot read %s: %s" % (args.pack, error.strerror), file=sys.stderr)
        return 2
    except PackError as error:
        print("pck_list: %s: %s" % (args.pack, error), file=sys.stderr)
        return 2
    files = [e for e in pack.entries if not e.flags & FILE_FLAG_REMOVAL]
    if args.list:
        for entry in sorted(files, key=lambda e: e.path):
            print("%10d  %s" % (entry.size, entry.path))
    print(
        "pck_list: %s: pack format %d, engine %s, flags: %s; %d files, %d bytes of file data, "
        "%d bytes in all"
        % (
            args.pack,
            pack.format_version,
            pack.engine,
            describe_flags(pack.flags),
            len(files),
            sum(e.size for e in files),
            len(data),
        )
    )
    dangling = dangling_classes(data, pack)
    if dangling:
        # Godot packs the editor's class cache as it is; a name without its script is inert.
        print(
            "pck_list: note: the packed class cache names %d script(s) left out of the pack: %s"
            % (len(dangling), " ".join(dangling))
        )
    forbidden = [e.path for e in files if any(fnmatch.fnmatchcase(e.path, p) for p in args.forbid)]
    for path in forbidden:
        print("pck_list: FORBIDDEN in the pack: %s" % path, file=sys.stderr)
    if forbidden:
        patterns = " ".join(args.forbid)
        print(
            "pck_list: %d forbidden file(s) (patterns: %s)" % (len(forbidden), patterns),
            file=sys.stderr,
        )
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
