#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Checks a PNG's pixels (8-bit RGB or RGBA, decoded here with zlib alone): its size, that it is not blank (the
standard deviation of its brightness), and that given regions hold drawing (pixels that differ from the background,
the top-left corner's colour). Regions are x0 y0 x1 y1 in [0, 1] of the width and height, from the top left.

check_png_pixels.py FILE WIDTH HEIGHT [--min-std S] [--drawn x0 y0 x1 y1 FRACTION]... [--blank x0 y0 x1 y1 FRACTION]...
--drawn: at least FRACTION of the region's pixels differ from the background; --blank: at most FRACTION do.
Exits 1 with a message naming the file and what is wrong."""
import argparse
import struct
import sys
import zlib


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else (b if pb <= pc else c)


def decode(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    offset, chunks, header = 8, [], None
    while offset < len(data):
        length, kind = struct.unpack(">I4s", data[offset:offset + 8])
        body = data[offset + 8:offset + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            chunks.append(body)
        offset += 12 + length
    width, height, depth, colour_type = header[:4]
    if depth != 8 or colour_type not in (2, 6):
        raise ValueError(f"bit depth {depth}, colour type {colour_type}: only 8-bit RGB(A) is read")
    channels = 3 if colour_type == 2 else 4
    raw = zlib.decompress(b"".join(chunks))
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            left = line[i - channels] if i >= channels else 0
            up = previous[i]
            corner = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 255
            elif kind == 4:
                line[i] = (line[i] + paeth(left, up, corner)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        previous = line
    return width, height, rows


def drawn_share(rows, region, background):
    height, width = len(rows), len(rows[0])
    x0, y0, x1, y1 = region
    total = drawn = 0
    for y in range(int(y0 * height), int(y1 * height)):
        for x in range(int(x0 * width), int(x1 * width)):
            total += 1
            drawn += sum(abs(a - b) for a, b in zip(rows[y][x], background)) > 30
    return drawn / max(total, 1)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("png")
    parser.add_argument("width", type=int)
    parser.add_argument("height", type=int)
    parser.add_argument("--min-std", type=float, default=10.0)
    parser.add_argument("--drawn", nargs=5, type=float, action="append", default=[])
    parser.add_argument("--blank", nargs=5, type=float, action="append", default=[])
    args = parser.parse_args()
    width, height, rows = decode(args.png)
    problems = []
    if (width, height) != (args.width, args.height):
        problems.append(f"{width}x{height}, expected {args.width}x{args.height}")
    brightness = [sum(p) / 3.0 for row in rows for p in row]
    mean = sum(brightness) / len(brightness)
    std = (sum((b - mean) ** 2 for b in brightness) / len(brightness)) ** 0.5
    print(f"{args.png}: {width}x{height}, brightness standard deviation {std:.1f}")
    if std < args.min_std:
        problems.append(f"nearly blank: brightness standard deviation {std:.1f} < {args.min_std}")
    background = rows[0][0]
    for *region, least in args.drawn:
        share = drawn_share(rows, region, background)
        print(f"  drawn in {region}: {share:.3f}")
        if share < least:
            problems.append(f"region {region}: {share:.3f} of its pixels drawn, expected at least {least}")
    for *region, most in args.blank:
        share = drawn_share(rows, region, background)
        print(f"  drawn in {region}: {share:.3f}")
        if share > most:
            problems.append(f"region {region}: {share:.3f} of its pixels drawn, expected at most {most}")
    if problems:
        sys.exit(f"{args.png}: " + "; ".join(problems))


if __name__ == "__main__":
    main()
