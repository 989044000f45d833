// SPDX-License-Identifier: BSD-3-Clause
#include "mesh_slicer.h"

#include <limits>

namespace morphreg
{
namespace synthetic
{
namespace
{
double
cross (const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
  return a.x () * b.y () - a.y () * b.x ();
}
} // namespace

std::vector<SliceSegment>
sliceAtHeight (const TriangleMesh& mesh, double height)
{
  std::vector<SliceSegment> segments;
  for (Eigen::Index t = 0; t < mesh.numTriangles (); ++t) {
    // A vertex counts as above the plane when y >= height, so every crossing edge is found exactly once.
    Eigen::Vector2d ends[2];
    Eigen::Vector3d barycentric[2];
    int found = 0;
    for (int edge = 0; edge < 3 && found < 2; ++edge) {
      const int i = edge, j = (edge + 1) % 3;
      const Eigen::Vector3d a = mesh.vertices.col (mesh.triangles (i, t));
      const Eigen::Vector3d b = mesh.vertices.col (mesh.triangles (j, t));
      if ((a.y () >= height) == (b.y () >= height))
        continue;
      const double s = (height - a.y ()) / (b.y () - a.y ());
      const Eigen::Vector3d p = a + s * (b - a);
      ends[found] = Eigen::Vector2d (p.x (), p.z ());
      barycentric[found].setZero ();
      barycentric[found][i] = 1.0 - s;
      barycentric[found][j] = s;
      ++found;
    }
    if (found == 2)
      segments.push_back ({static_cast<int> (t), ends[0], ends[1], barycentric[0], barycentric[1]});
  }
  return segments;
}

SliceHit
firstHit (const std::vector<SliceSegment>& segments, const Eigen::Vector2d& origin, const Eigen::Vector2d& direction)
{
  SliceHit hit;
  double nearest = std::numeric_limits<double>::infinity ();
  for (std::size_t k = 0; k < segments.size (); ++k) {
    const Eigen::Vector2d edge = segments[k].end - segments[k].start;
    const double denominator = cross (direction, edge);
    if (std::abs (denominator) < 1e-12)
      continue; // parallel to the ray
    const Eigen::Vector2d to_start = segments[k].start - origin;
    const double t = cross (to_start, edge) / denominator;
    const double s = cross (to_start, direction) / denominator;
    if (t > 0.0 && t < nearest && s >= 0.0 && s <= 1.0) {
      nearest = t;
      hit = {static_cast<int> (k), s};
    }
  }
  return hit;
}

} // namespace synthetic
} // namespace morphreg
