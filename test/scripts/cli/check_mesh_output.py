#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Runs `morphreg register ... --out OUT` and reads OUT back, independently of morphreg's readers: the "wrote" line
must say what the format carries, and the file must carry it.

  .ply: uchar red/green/blue and float quality (no curvature); the quality is the residual: its mean, RMS and max
        are the report's residuals_mm.per_vertex figures.
  .obj: every v line is x y z r g b with r g b in [0, 1], not all one colour; the message says OBJ has no field for
        the residual values.
  .vtk: COLOR_SCALARS; the message does not promise a quality field.

usage: check_mesh_output.py MORPHREG OUT [register arguments ...]
"""
import json
import math
import struct
import subprocess
import sys

PLY_TYPES = {"char": "b", "uchar": "B", "short": "h", "ushort": "H", "int": "i", "uint": "I", "float": "f",
             "double": "d", "int8": "b", "uint8": "B", "int16": "h", "uint16": "H", "int32": "i", "uint32": "I",
             "float32": "f", "float64": "d"}


def fail(message):
    print("FAILED: " + message)
    sys.exit(1)


def ply_vertices(path):
    """The vertex element of a binary little-endian PLY as a dict of property name -> list of values."""
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    if "format binary_little_endian 1.0" not in header:
        fail(f"{path}: not binary little-endian: {header[:3]}")
    count, names, layout, element = 0, [], "<", None
    for line in header:
        words = line.split()
        if words[:1] == ["element"]:
            element = words[1]
            if element == "vertex":
                count = int(words[2])
        elif words[:1] == ["property"] and element == "vertex":
            if words[1] == "list":
                fail(f"{path}: list property in the vertex element")
            names.append(words[2])
            layout += PLY_TYPES[words[1]]
    size = struct.calcsize(layout)
    rows = [struct.unpack_from(layout, data, end + i * size) for i in range(count)]
    return {name: [row[k] for row in rows] for k, name in enumerate(names)}, "\n".join(header)


def check_ply(path, report):
    vertices, header = ply_vertices(path)
    for name in ("red", "green", "blue", "quality"):
        if name not in vertices:
            fail(f"{path}: no vertex property '{name}' in\n{header}")
    if "curvature" in vertices:
        fail(f"{path}: still has a curvature property")
    quality = vertices["quality"]
    expected = report["residuals_mm"]["per_vertex"]
    figures = {"mean": sum(quality) / len(quality), "max": max(quality),
               "rms": math.sqrt(sum(q * q for q in quality) / len(quality))}
    for name, value in figures.items():
        if abs(value - expected[name]) > 1e-4 * max(1.0, expected[name]):
            fail(f"{path}: quality {name} {value}, the report's per-vertex residual {name} is {expected[name]}")
    if len(set(zip(vertices["red"], vertices["green"], vertices["blue"]))) < 2:
        fail(f"{path}: every vertex has the same colour")
    print(f"{path}: {len(quality)} vertices, quality = residual (RMS {figures['rms']:.4f} mm), colours")


def check_obj(path):
    colours = set()
    for line in open(path):
        if line.startswith("v "):
            values = [float(v) for v in line.split()[1:]]
            if len(values) != 6 or not all(0.0 <= c <= 1.0 for c in values[3:]):
                fail(f"{path}: vertex line without an r g b colour in [0, 1]: {line.strip()}")
            colours.add(tuple(values[3:]))
    if len(colours) < 2:
        fail(f"{path}: {len(colours)} distinct vertex colours")
    print(f"{path}: v x y z r g b lines, {len(colours)} distinct colours")


def main():
    morphreg, out, arguments = sys.argv[1], sys.argv[2], sys.argv[3:]
    report_path = out + ".json"
    run = subprocess.run([morphreg, "register", *arguments, "--out", out, "--report", report_path],
                         capture_output=True, text=True)
    if run.returncode != 0:
        fail(f"register exited {run.returncode}:\n{run.stdout}\n{run.stderr}")
    wrote = [line for line in run.stdout.splitlines() if line.startswith("wrote " + out)]
    if not wrote:
        fail(f"no 'wrote {out}' line in:\n{run.stdout}")
    message = wrote[0]
    print(message)
    if not message.startswith(f"wrote {out} (vertex colours"):
        fail("the message does not say the mesh carries vertex colours")
    promises_quality = "vertex quality: residual in mm" in message
    if out.endswith(".ply"):
        if not promises_quality:
            fail("the PLY message does not name the quality field")
        check_ply(out, json.load(open(report_path)))
    elif out.endswith(".obj"):
        if promises_quality or "v x y z r g b" not in message or "obj has no field for the residual" not in message:
            fail("the OBJ message must name v x y z r g b and say the residual values are not in the file")
        check_obj(out)
    else:
        if promises_quality or "COLOR_SCALARS" not in open(out, errors="replace").read():
            fail("a VTK file carries colours (COLOR_SCALARS) and no quality")
    print("ok")


if __name__ == "__main__":
    main()
