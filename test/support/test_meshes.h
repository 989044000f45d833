// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Small meshes with known answers for the unit tests.
#include <morphreg/mesh/triangle_mesh.h>

namespace morphreg
{
namespace test
{
/** An axis-aligned cube of edge \a size centred at the origin: 8 vertices, 12 outward triangles. */
inline TriangleMesh
makeCube (double size = 2.0)
{
  TriangleMesh cube;
  cube.vertices.resize (3, 8);
  for (int i = 0; i < 8; ++i)
    cube.vertices.col (i) = 0.5 * size * Eigen::Vector3d (i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  const int faces[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                            {2, 7, 3}, {2, 6, 7}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  cube.triangles.resize (3, 12);
  for (int t = 0; t < 12; ++t)
    cube.triangles.col (t) = Eigen::Vector3i (faces[t][0], faces[t][1], faces[t][2]);
  return cube;
}

/** A flat (z = 0) grid of n x n vertices with spacing \a step, two triangles per cell (an open surface). */
inline TriangleMesh
makeGrid (int n, double step = 1.0)
{
  TriangleMesh grid;
  grid.vertices.resize (3, n * n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c)
      grid.vertices.col (r * n + c) = Eigen::Vector3d (c * step, r * step, 0.0);
  grid.triangles.resize (3, 2 * (n - 1) * (n - 1));
  int t = 0;
  for (int r = 0; r + 1 < n; ++r)
    for (int c = 0; c + 1 < n; ++c) {
      const int v = r * n + c;
      grid.triangles.col (t++) = Eigen::Vector3i (v, v + 1, v + n + 1);
      grid.triangles.col (t++) = Eigen::Vector3i (v, v + n + 1, v + n);
    }
  return grid;
}
} // namespace test
} // namespace morphreg
