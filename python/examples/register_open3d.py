# SPDX-License-Identifier: BSD-3-Clause
"""Registers a morphreg head model to a scan read with Open3D, and writes the fitted mesh with Open3D.

Usage: python3 register_open3d.py MODEL.h5 SCAN.ply FITTED.ply
The scan is any point cloud Open3D reads (PLY, PCD, XYZ...); normals are estimated when it has none.
"""
import sys

import numpy as np
import open3d as o3d

import morphreg


def main(model_path, scan_path, out_path):
    model = morphreg.Model.load(model_path)
    scan = o3d.io.read_point_cloud(scan_path)
    if not scan.has_points():
        sys.exit(f"{scan_path}: Open3D read no points")
    if not scan.has_normals():
        scan.estimate_normals(o3d.geometry.KDTreeSearchParamKNN(20))
    # Open3D's vectors are (N, 3) float64 in C order: morphreg reads them without a copy.
    points, normals = np.asarray(scan.points), np.asarray(scan.normals)

    def show(iteration, correspondences, rms):
        print(f"\riteration {iteration}: {correspondences} correspondences, RMS {rms:.3f} mm", end="", flush=True)

    result = morphreg.register(model, points, normals, components=10, progress=show)
    print(f"\n{result.status}: scale {result.scale:.4f}, scan-to-model RMS "
          f"{result.report['residuals_mm']['scan_to_model']['rms']:.3f} mm")
    fitted = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(result.vertices),
                                       o3d.utility.Vector3iVector(result.faces))
    fitted.compute_vertex_normals()
    if not o3d.io.write_triangle_mesh(out_path, fitted):
        sys.exit(f"{out_path}: Open3D could not write it")
    print(f"wrote {out_path}")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
