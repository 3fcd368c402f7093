#!/usr/bin/env python3
"""Prints the mean brightness (0-255) of a binary PPM (P6) image, such as xwdtopnm writes.

The release check tells the dark menus from the light maze board with it.
Usage: mean_brightness.py IMAGE.ppm
"""

import sys


def _header_fields(data):
    fields, pos = [], 0
    while len(fields) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos)
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    return fields, pos + 1


def mean_brightness(data):
    """The mean of every channel of every pixel of a P6 image with 8-bit samples."""
    fields, start = _header_fields(data)
    if fields[0] != b"P6" or int(fields[3]) > 255:
        raise ValueError("not an 8-bit binary PPM")
    width, height = int(fields[1]), int(fields[2])
    pixels = data[start:start + width * height * 3]
    if len(pixels) < width * height * 3:
        raise ValueError("the image is cut short")
    return sum(pixels) / len(pixels)


def main(argv):
    if len(argv) != 1:
        print("usage: mean_brightness.py IMAGE.ppm", file=sys.stderr)
        return 2
    try:
        with open(argv[0], "rb") as handle:
            print(int(mean_brightness(handle.read())))
    except (OSError, ValueError, IndexError) as error:
        print("mean_brightness: %s: %s" % (argv[0], error), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
