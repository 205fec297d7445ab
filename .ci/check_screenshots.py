#!/usr/bin/env python3
"""Checks an example's screenshots: each shows a scene, and they differ (it animates).

usage: check_screenshots.py NAME FIRST.png LAST.png

A screenshot "shows the scene" when at least MIN_DRAWN of its pixels differ from its most
common colour (the clear colour) and it has at least MIN_COLOURS distinct colours; the example
"animates" when at least MIN_CHANGED of the pixels differ between the two screenshots.
Pure Python (zlib only): CI needs no image libraries.
"""

import struct
import sys
import zlib
from collections import Counter

MIN_DRAWN = 0.01
MIN_COLOURS = 8
MIN_CHANGED = 0.001


def read_png(path):
    """Decodes an 8-bit RGB or RGBA, non-interlaced PNG into (width, height, rows of pixels)."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG")
    pos, idat, header = 8, [], None
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos : pos + 4])
        kind = data[pos + 4 : pos + 8]
        body = data[pos + 8 : pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            break
    width, height, depth, colour, _, _, interlace = header
    channels = {2: 3, 6: 4}.get(colour)
    if depth != 8 or channels is None or interlace != 0:
        raise ValueError(f"{path}: unsupported PNG (depth {depth}, colour {colour})")
    raw = zlib.decompress(b"".join(idat))
    stride = width * channels
    rows, previous, i = [], bytearray(stride), 0
    for _ in range(height):
        kind, line = raw[i], bytearray(raw[i + 1 : i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            left = line[x - channels] if x >= channels else 0
            up = previous[x]
            up_left = previous[x - channels] if x >= channels else 0
            if kind == 1:
                line[x] = (line[x] + left) & 0xFF
            elif kind == 2:
                line[x] = (line[x] + up) & 0xFF
            elif kind == 3:
                line[x] = (line[x] + (left + up) // 2) & 0xFF
            elif kind == 4:
                p = left + up - up_left
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - up_left)
                pred = left if pa <= pb and pa <= pc else (up if pb <= pc else up_left)
                line[x] = (line[x] + pred) & 0xFF
        rows.append(bytes(line))
        previous = line
    pixels = [
        row[x : x + 3] for row in rows for x in range(0, stride, channels)
    ]
    return width, height, pixels


def main():
    name, first, last = sys.argv[1], sys.argv[2], sys.argv[3]
    failures = []
    decoded = []
    for path in (first, last):
        width, height, pixels = read_png(path)
        decoded.append(pixels)
        counts = Counter(pixels)
        background, most = counts.most_common(1)[0]
        drawn = 1 - most / len(pixels)
        print(
            f"{name}: {path}: {width}x{height}, {len(counts)} colours, "
            f"{drawn:.1%} drawn over background {tuple(background)}"
        )
        if drawn < MIN_DRAWN or len(counts) < MIN_COLOURS:
            failures.append(f"{path} looks empty")
    a, b = decoded
    if len(a) != len(b):
        failures.append("screenshots differ in size")
    else:
        changed = sum(1 for p, q in zip(a, b) if p != q) / len(a)
        print(f"{name}: {changed:.1%} of pixels changed between the screenshots")
        if changed < MIN_CHANGED:
            failures.append("nothing moved between the screenshots")
    for failure in failures:
        print(f"{name}: FAIL: {failure}", file=sys.stderr)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
