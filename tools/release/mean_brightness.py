#!/usr/bin/env python3
"""Prints the mean brightness (0-255) of a binary PPM (P6) image, such as xwdtopnm writes
(8-bit samples, or 16-bit ones, which some netpbm releases write for a 24-bit screen).

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
    maxval = int(fields[3])
    if fields[0] != b"P6" or not 0 < maxval <= 65535:
        raise ValueError("not a binary PPM")
    width, height = int(fields[1]), int(fields[2])
    sample_bytes = 1 if maxval <= 255 else 2
    size = width * height * 3 * sample_bytes
    pixels = data[start:start + size]
    if len(pixels) < size:
        raise ValueError("the image is cut short")
    if sample_bytes == 1:
        return sum(pixels) * 255 / (len(pixels) * maxval)
    samples = memoryview(pixels).cast("H") if sys.byteorder == "big" else None
    total = sum(samples) if samples is not None else _big_endian_sum(pixels)
    return total * 255 / ((len(pixels) // 2) * maxval)


def _big_endian_sum(pixels):
    """The sum of 16-bit big-endian samples (PPM's order) on a little-endian machine."""
    return sum(pixels[0::2]) * 256 + sum(pixels[1::2])


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
