#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes the bad-input catalogue's crafted binary files (test/scripts/cli_catalogue.cmake) into OUT:

- corrupt copies of a model file MODEL (h5py): a flipped bit in the mean, a region basis scaled by 1000, every
  triangle (0, 0, 0), a mean coordinate of 1e30 in every copy, landmark vertices that are not whole numbers in range,
  an unknown landmark id, and bytes overwritten inside the HDF5 structure;
- photos whose headers lie: PNG and JPEG headers declaring 100000 x 100000 (JPEG: 60000 x 60000) pixels in 200
  bytes, a JPEG cut before
  its image data, a JPEG of four (CMYK) components, and a PNG cut after its header.

usage: make_bad_inputs.py MODEL OUT
"""
import json
import shutil
import struct
import sys
import zlib

import h5py
import numpy as np


def corrupt(model, out, name, change):
    path = f"{out}/{name}.h5"
    shutil.copyfile(model, path)
    with h5py.File(path, "r+") as f:
        change(f)


def replace(f, name, data):
    del f[name]
    if isinstance(data, str):
        f.create_dataset(name, data=data, dtype=h5py.string_dtype())
    else:
        f.create_dataset(name, data=data)


def flip_mean_bit(f):
    mean = f["morphreg/mean"][...]
    bits = mean.view(np.uint64)
    bits[30] ^= np.uint64(1) << np.uint64(62)  # the top exponent bit: the coordinate moves far
    f["morphreg/mean"][...] = bits.view(np.float64)


def scale_basis(f):
    basis = f["morphreg/regions/region_0/basis"]
    basis[...] = basis[...] * 1000.0


def zero_triangles(f):
    cells = f["representer/cells"]
    cells[...] = np.zeros(cells.shape, dtype=cells.dtype)


def huge_mean(f):
    for name in ("morphreg/mean", "model/mean"):
        values = f[name][...]
        values[0] = 1e30
        f[name][...] = values
    points = f["representer/points"][...]
    points[0, 0] = 1e30
    f["representer/points"][...] = points


def landmarks(text_change):
    def change(f):
        value = f["morphreg/landmarks"][()]
        text = value.decode() if isinstance(value, bytes) else value
        replace(f, "morphreg/landmarks", text_change(json.loads(text)))
    return change


def set_first(value):
    def change(landmark_map):
        first = sorted(landmark_map)[0]
        landmark_map[first] = value
        return json.dumps(landmark_map)
    return change


def unknown_id(landmark_map):
    landmark_map["not_a_landmark"] = 0
    return json.dumps(landmark_map)


def write_models(model, out):
    corrupt(model, out, "model_mean_bit_flip", flip_mean_bit)
    corrupt(model, out, "model_basis_scaled", scale_basis)
    corrupt(model, out, "model_triangles_zero", zero_triangles)
    corrupt(model, out, "model_mean_huge", huge_mean)
    corrupt(model, out, "model_landmark_wraps", landmarks(set_first(4294967301)))
    corrupt(model, out, "model_landmark_fraction", landmarks(set_first(12.9)))
    corrupt(model, out, "model_landmark_unknown", landmarks(unknown_id))
    data = bytearray(open(model, "rb").read())
    data[600:1400] = bytes(800)  # inside the superblock's root group and its first object headers
    open(f"{out}/model_structure_zeroed.h5", "wb").write(bytes(data))


def png_chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def write_photos(out):
    header = png_chunk(b"IHDR", struct.pack(">IIBBBBB", 100000, 100000, 8, 2, 0, 0, 0))
    huge = b"\x89PNG\r\n\x1a\n" + header + png_chunk(b"IDAT", zlib.compress(bytes(100)))
    open(f"{out}/huge.png", "wb").write(huge + bytes(max(0, 200 - len(huge))))
    small = png_chunk(b"IHDR", struct.pack(">IIBBBBB", 64, 64, 8, 2, 0, 0, 0))
    open(f"{out}/header_only.png", "wb").write(b"\x89PNG\r\n\x1a\n" + small)

    def jpeg(width, height, components, tail):
        frame = struct.pack(">BHHB", 8, height, width, components)
        for c in range(components):
            frame += struct.pack(">BBB", c + 1, 0x11, 0)
        sof = b"\xff\xc0" + struct.pack(">H", 2 + len(frame)) + frame
        return b"\xff\xd8" + b"\xff\xe0" + struct.pack(">H", 16) + b"JFIF\x00\x01\x01\x00\x00\x01\x00\x01\x00\x00" + sof + tail

    big = jpeg(60000, 60000, 3, b"")
    open(f"{out}/huge.jpg", "wb").write(big + bytes(max(0, 200 - len(big))))
    open(f"{out}/no_scan.jpg", "wb").write(jpeg(64, 64, 3, b"\xff\xd9"))
    open(f"{out}/cmyk.jpg", "wb").write(jpeg(64, 64, 4, bytes(600) + b"\xff\xd9"))


def main():
    model, out = sys.argv[1], sys.argv[2]
    write_models(model, out)
    write_photos(out)


if __name__ == "__main__":
    main()
