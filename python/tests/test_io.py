# SPDX-License-Identifier: BSD-3-Clause
"""Mesh, cloud and landmark files through the library's readers and writers."""
import base64
import json
import struct

import numpy as np
import pytest

import morphreg


@pytest.mark.parametrize("extension, relative", [(".ply", 1e-7), (".obj", 1e-7), (".vtk", 1e-4)])
def test_mesh_round_trip(truth, tmp_path, extension, relative):
    path = str(tmp_path / ("head" + extension))
    morphreg.save_mesh(path, truth.vertices, truth.faces)
    vertices, faces = morphreg.load_mesh(path)
    assert faces.dtype == np.int32 and np.array_equal(faces, truth.faces)
    # The files hold float32 (PLY, OBJ) or 5 significant digits (PCL's legacy VTK writer).
    assert np.allclose(vertices, truth.vertices, rtol=relative, atol=1e-4)


def test_cloud_round_trip_with_and_without_normals(scan, tmp_path):
    with_normals, without = str(tmp_path / "n.pcd"), str(tmp_path / "p.ply")
    morphreg.save_cloud(with_normals, scan.points, scan.normals)
    morphreg.save_cloud(without, scan.points.astype(np.float32))
    points, normals = morphreg.load_cloud(with_normals)
    assert np.allclose(points, scan.points, atol=1e-4) and np.allclose(normals, scan.normals, atol=1e-6)
    points, normals = morphreg.load_cloud(without)
    assert normals is None and points.shape == scan.points.shape


@pytest.mark.parametrize("extension", [".json", ".pp", ".csv"])
def test_landmark_round_trip(tmp_path, extension):
    landmarks = {"nose_tip": np.array([1.0, 2.0, 3.0]), "chin": np.array([0.5, -80.0, 10.0])}
    path = str(tmp_path / ("marks" + extension))
    morphreg.save_landmarks(path, landmarks)
    loaded = morphreg.load_landmarks(path)
    assert sorted(loaded) == sorted(landmarks)
    for name in landmarks:
        assert np.allclose(loaded[name], landmarks[name])


def test_missing_and_corrupt_files_are_named(tmp_path):
    with pytest.raises(morphreg.IoError, match="nowhere.ply"):
        morphreg.load_mesh(str(tmp_path / "nowhere.ply"))
    bad = tmp_path / "bad.ply"
    bad.write_text("ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nend_header\n1\n")
    with pytest.raises(morphreg.FormatError, match="bad.ply"):
        morphreg.load_cloud(str(bad))
    renamed = tmp_path / "renamed.pcd"
    renamed.write_bytes(bad.read_bytes())
    with pytest.raises(morphreg.FormatError, match="renamed.pcd"):
        morphreg.load_cloud(str(renamed))
    marks = tmp_path / "marks.json"
    marks.write_text("{not json")
    with pytest.raises(morphreg.FormatError, match="marks.json"):
        morphreg.load_landmarks(str(marks))


def test_bad_arrays_are_named(truth, tmp_path):
    path = str(tmp_path / "x.ply")
    with pytest.raises(morphreg.InvalidInputError, match="face 2 has vertex index 9999"):
        faces = truth.faces.copy()
        faces[2, 1] = 9999
        morphreg.save_mesh(path, truth.vertices, faces)
    with pytest.raises(morphreg.InvalidInputError, match="dtype float64, expected integers"):
        morphreg.save_mesh(path, truth.vertices, truth.faces.astype(float))
    with pytest.raises(morphreg.InvalidInputError, match="normals"):
        morphreg.save_cloud(path, truth.vertices, truth.vertices[:10])
    with pytest.raises(morphreg.InvalidInputError, match="nose_tip"):
        morphreg.save_landmarks(str(tmp_path / "m.json"), {"nose_tip": [np.nan, 0, 0]})
    with pytest.raises(morphreg.IoError, match="no_such_folder"):
        morphreg.save_mesh(str(tmp_path / "no_such_folder" / "x.ply"), truth.vertices, truth.faces)


def gltf_parts(vertices, faces):
    """A one-primitive glTF of the mesh in metres: its JSON and its binary buffer (positions, then indices)."""
    positions = (np.asarray(vertices) / 1000.0).astype("<f4").tobytes()
    indices = np.asarray(faces).astype("<u4").tobytes()
    document = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": len(vertices), "type": "VEC3"},
                      {"bufferView": 1, "componentType": 5125, "count": faces.size, "type": "SCALAR"}],
        "bufferViews": [{"buffer": 0, "byteLength": len(positions)},
                        {"buffer": 0, "byteOffset": len(positions), "byteLength": len(indices)}],
        "buffers": [{"byteLength": len(positions) + len(indices)}]}
    return document, positions + indices


def test_gltf_and_glb_are_read_in_millimetres(truth, tmp_path):
    document, buffer = gltf_parts(truth.vertices, truth.faces)
    text = json.dumps(document).encode()
    text += b" " * (-len(text) % 4)
    glb = tmp_path / "head.glb"
    glb.write_bytes(b"glTF" + struct.pack("<II", 2, 28 + len(text) + len(buffer)) + struct.pack("<I", len(text))
                    + b"JSON" + text + struct.pack("<I", len(buffer)) + b"BIN\0" + buffer)
    document["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(buffer).decode()
    embedded = tmp_path / "head.gltf"
    embedded.write_text(json.dumps(document))
    for path in (glb, embedded):
        vertices, faces = morphreg.load_mesh(str(path))
        assert np.array_equal(faces, truth.faces)
        assert np.allclose(vertices, truth.vertices, rtol=1e-6, atol=1e-4)  # metres in float32, read in mm
        points, normals = morphreg.load_cloud(str(path))
        assert normals is None and np.allclose(points, truth.vertices, rtol=1e-6, atol=1e-4)
    glb.write_bytes(glb.read_bytes()[:100])
    with pytest.raises(morphreg.FormatError, match="head.glb: the GLB header gives a length of"):
        morphreg.load_mesh(str(glb))

