#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Independent HDF5 reader/writer (h5py) for the model-file tests: it follows the statismo v0.9 layout as
documented in include/morphreg/io/model_io.h and shares no code with morphreg.

  statismo_fixture.py write <dir>          writes statismo-layout files (valid and corrupt) and expected.json
  statismo_fixture.py verify <file.h5>     checks a morphreg-written file against the layout; exit 1 on problems
  statismo_fixture.py break-region <src> <dst>   copies src with a region vertex index out of range
"""
import json
import os
import shutil
import struct
import sys

import h5py
import numpy as np


def cube():
    """A head-sized cube in mm (RMS radius 173 mm), so that its unit guessed from its size is mm."""
    points = np.array([[x, y, z] for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)], dtype=np.float64) * 100.0
    cells = np.array([[0, 2, 3], [0, 3, 1], [4, 5, 7], [4, 7, 6], [0, 1, 5], [0, 5, 4],
                      [2, 7, 3], [2, 6, 7], [0, 4, 6], [0, 6, 2], [1, 3, 7], [1, 7, 5]], dtype=np.int32)
    return points, cells


def write_model(path, prefix="", minor=9, scaled=False, version_at_root=False, edit=None, mm_per_unit=1.0):
    """The cube model, stored in a unit of mm_per_unit mm (coordinates divided by it, variances by its square)."""
    points, cells = cube()
    n = points.shape[0]
    rng = np.random.default_rng(4)
    basis, _ = np.linalg.qr(rng.standard_normal((3 * n, 3)))
    variances = np.array([9.0, 4.0, 1.0])
    mean = points.reshape(-1) + 0.5
    stored_variances = variances / mm_per_unit ** 2
    stored_basis = basis * np.sqrt(stored_variances) if scaled else basis
    data = {
        "model/mean": (mean / mm_per_unit).astype(np.float32),
        "model/pcaBasis": stored_basis.astype(np.float32),
        "model/pcaVariance": stored_variances.astype(np.float32),
        "model/noiseVariance": np.float32(0.25 / mm_per_unit ** 2),
        "representer/points": (points.T / mm_per_unit).astype(np.float32),
        "representer/cells": cells.T.copy(),
    }
    if edit:
        edit(data)
    with h5py.File(path, "w") as f:
        root = f.create_group(prefix) if prefix else f
        for name, value in data.items():
            if value is not None:
                root.create_dataset(name, data=value)
        root["representer"].attrs["name"] = "fixture mesh representer"
        root["representer"].attrs["datasetType"] = "POLYGON_MESH"
        version = f.require_group("version") if version_at_root else root.require_group("version")
        version.create_dataset("majorVersion", data=np.int32(0))
        version.create_dataset("minorVersion", data=np.int32(minor))
        if prefix:  # a second model in the same file, as BFM-2017 has a colour model
            f.create_group("color/model").create_dataset("mean", data=np.zeros(3 * n, np.float32))
    return {"mean": mean.tolist(), "basis": basis.tolist(), "variances": variances.tolist(),
            "cells": cells.tolist(), "noise_variance": 0.25}


def set_item(name, transform):
    def edit(data):
        data[name] = transform(data[name])
    return edit


def nan_first(a):
    a = a.copy()
    a[0] = np.nan
    return a


def bad_cell(a):
    a = a.copy()
    a[1, 2] = 8
    return a


def write(directory):
    expected = write_model(os.path.join(directory, "statismo_v09.h5"))
    bfm = write_model(os.path.join(directory, "bfm2017_style.h5"), prefix="shape", version_at_root=True)
    # BFM-2017 keeps scalismo landmark JSON (positions near the mean) in metadata/landmarks/json.
    mean = np.array(bfm["mean"]).reshape(-1, 3)
    landmarks = [{"id": "center.nose.tip", "coordinates": (mean[6] + 0.1).tolist(), "uncertainty": {}},
                 {"id": "left.ear.helix.top", "coordinates": mean[1].tolist()}]
    with h5py.File(os.path.join(directory, "bfm2017_style.h5"), "r+") as f:
        f.create_dataset("metadata/landmarks/json", data=json.dumps(landmarks))
    write_model(os.path.join(directory, "bfm2017_bad_landmarks.h5"), prefix="shape", version_at_root=True)
    with h5py.File(os.path.join(directory, "bfm2017_bad_landmarks.h5"), "r+") as f:
        f.create_dataset("metadata/landmarks/json", data=json.dumps([{"id": "center.nose.tip", "coordinates": [1]}]))
    # The global heap that holds the landmark JSON string, with its free space shrunk to a size of 0: HDF5 1.10 loops
    # forever walking such a heap collection.
    shutil.copyfile(os.path.join(directory, "bfm2017_style.h5"), os.path.join(directory, "corrupt_string_heap.h5"))
    with open(os.path.join(directory, "corrupt_string_heap.h5"), "r+b") as f:
        data = f.read()
        at = data.rindex(b"GCOL") + 16  # the last collection, written with the landmark JSON
        while struct.unpack_from("<H", data, at)[0] != 0:  # walk to the free space (index 0)
            at += 16 + (struct.unpack_from("<Q", data, at + 8)[0] + 7) // 8 * 8
        f.seek(at + 8)
        f.write(struct.pack("<Q", 0))
    # The same model in cm and m, which statismo files cannot say: recognised by their size; and in micrometres,
    # which no unit makes a head.
    write_model(os.path.join(directory, "statismo_centimetres.h5"), mm_per_unit=10.0)
    write_model(os.path.join(directory, "statismo_metres.h5"), mm_per_unit=1000.0)
    write_model(os.path.join(directory, "statismo_micrometres.h5"), mm_per_unit=0.001)
    write_model(os.path.join(directory, "statismo_v08.h5"), minor=8, scaled=True)
    write_model(os.path.join(directory, "scaled_labelled_v09.h5"), minor=9, scaled=True)
    write_model(os.path.join(directory, "missing_variance.h5"), edit=set_item("model/pcaVariance", lambda a: None))
    write_model(os.path.join(directory, "wrong_basis_dims.h5"), edit=set_item("model/pcaBasis", lambda a: a[3:, :]))
    write_model(os.path.join(directory, "nan_mean.h5"), edit=set_item("model/mean", nan_first))
    write_model(os.path.join(directory, "bad_cell_index.h5"), edit=set_item("representer/cells", bad_cell))
    write_model(os.path.join(directory, "wrong_points_rank.h5"),
                edit=set_item("representer/points", lambda a: a.reshape(-1)))
    # [3, N] points whose element count 3N wraps around 2^64 to 2: no data is stored (chunked, never written).
    write_model(os.path.join(directory, "wrapping_points_dims.h5"), edit=set_item("representer/points", lambda a: None))
    with h5py.File(os.path.join(directory, "wrapping_points_dims.h5"), "r+") as f:
        f.create_dataset("representer/points", shape=(3, (2 ** 64 + 2) // 3), dtype=np.float32, chunks=(3, 1))
    with open(os.path.join(directory, "statismo_v09.h5"), "rb") as f:
        whole = f.read()
    with open(os.path.join(directory, "truncated.h5"), "wb") as f:
        f.write(whole[: len(whole) // 2])
    with open(os.path.join(directory, "not_hdf5.h5"), "w") as f:
        f.write("this is not an HDF5 file\n")
    with open(os.path.join(directory, "expected.json"), "w") as f:
        json.dump(expected, f)


def verify(path):
    problems = []

    def check(condition, message):
        if not condition:
            problems.append(message)

    with h5py.File(path, "r") as f:
        for name in ("model/mean", "model/pcaBasis", "model/pcaVariance", "model/noiseVariance",
                     "representer/points", "representer/cells", "version/majorVersion", "version/minorVersion"):
            check(name in f, "missing " + name)
        if problems:
            return problems
        mean, basis, variance = f["model/mean"], f["model/pcaBasis"], f["model/pcaVariance"]
        for d in (mean, basis, variance, f["model/noiseVariance"], f["representer/points"]):
            check(d.dtype == np.float32, d.name + " is not float32")
        n3 = mean.shape[0]
        check(mean.ndim == 1 and n3 % 3 == 0, "mean is not [3N]")
        check(basis.shape == (n3, variance.shape[0]), "pcaBasis is not [3N, k]")
        u = basis[()].astype(np.float64)
        check(np.abs(u.T @ u - np.eye(u.shape[1])).max() < 1e-5, "pcaBasis columns are not orthonormal")
        check(np.all(np.diff(variance[()]) <= 0), "pcaVariance is not sorted")
        points = f["representer/points"][()]
        check(points.shape == (3, n3 // 3), "representer/points is not [3, N]")
        check(np.allclose(points.T.reshape(-1), mean[()]), "representer/points differ from the mean")
        cells = f["representer/cells"]
        check(cells.dtype.kind == "i" and cells.shape[0] == 3, "representer/cells is not int [3, M]")
        check(cells[()].min() >= 0 and cells[()].max() < n3 // 3, "representer/cells index out of range")
        check(int(f["version/majorVersion"][()]) == 0 and int(f["version/minorVersion"][()]) == 9, "version is not 0.9")
        rep = f["representer"].attrs
        check(rep.get("datasetType") in ("POLYGON_MESH", b"POLYGON_MESH"), "representer datasetType")
        check("name" in rep, "representer name attribute")
        check("modelinfo" in f, "missing modelinfo")
        m = f["morphreg"]
        weights = np.zeros(n3 // 3)
        for j in range(int(m["numRegions"][()])):
            r = m["regions/region_%d" % j]
            b = r["vertices"].shape[0]
            check(r["basis"].shape == (3 * b, r["variances"].shape[0]), "region %d basis shape" % j)
            np.add.at(weights, r["vertices"][()], r["weights"][()])
        check(np.allclose(weights, 1.0), "region weights do not sum to 1")
    return problems


def break_region(source, destination):
    shutil.copyfile(source, destination)
    with h5py.File(destination, "r+") as f:
        vertices = f["morphreg/regions/region_0/vertices"]
        vertices[0] = f["model/mean"].shape[0] // 3 + 5


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "write":
        write(sys.argv[2])
    elif len(sys.argv) == 3 and sys.argv[1] == "verify":
        found = verify(sys.argv[2])
        for problem in found:
            print(problem)
        sys.exit(1 if found else 0)
    elif len(sys.argv) == 4 and sys.argv[1] == "break-region":
        break_region(sys.argv[2], sys.argv[3])
    else:
        print(__doc__)
        sys.exit(2)
