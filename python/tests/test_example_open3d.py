# SPDX-License-Identifier: BSD-3-Clause
"""The Open3D example (python/examples/register_open3d.py) run as a user would, on a simulated scan."""
import os
import subprocess
import sys

import numpy as np
import open3d as o3d

import morphreg


def test_open3d_example_registers_a_scan(model_file, scan, truth, tmp_path):
    scan_file, fitted_file = str(tmp_path / "scan.ply"), str(tmp_path / "fitted.ply")
    morphreg.save_cloud(scan_file, scan.points)  # without normals: the example estimates them with Open3D
    example = os.path.join(os.environ["MORPHREG_PYTHON_EXAMPLES"], "register_open3d.py")
    run = subprocess.run([sys.executable, example, model_file, scan_file, fitted_file], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert "ok: scale" in run.stdout and "wrote " + fitted_file in run.stdout
    fitted = o3d.io.read_triangle_mesh(fitted_file)
    vertices = np.asarray(fitted.vertices)
    pose = scan.head_to_scan
    expected = truth.vertices @ pose[:3, :3].T + pose[:3, 3]
    assert len(fitted.triangles) == len(truth.faces)
    assert np.sqrt(np.mean(np.sum((vertices - expected) ** 2, axis=1))) < 2.0  # mm
