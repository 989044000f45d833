// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Horizontal slices of a triangle mesh: the 2D outline a cylindrical scanner's row of rays meets.
#include <morphreg/mesh/triangle_mesh.h>

#include <vector>

namespace morphreg
{
namespace synthetic
{
/** One triangle's cut by the plane y = const: a segment in the (x, z) plane, with the barycentric
 *  coordinates of its ends in that triangle. */
struct SliceSegment
{
  int triangle;
  Eigen::Vector2d start, end;
  Eigen::Vector3d start_barycentric, end_barycentric;
};

/** The segments where the plane y = \a height cuts \a mesh's triangles. */
std::vector<SliceSegment>
sliceAtHeight (const TriangleMesh& mesh, double height);

/** Where a ray first meets a slice: segment index and position along it (0 = start, 1 = end). */
struct SliceHit
{
  int segment = -1;
  double along = 0.0;
};

/** The first segment the 2D ray \a origin + t \a direction (t > 0) meets, or segment -1. */
SliceHit
firstHit (const std::vector<SliceSegment>& segments, const Eigen::Vector2d& origin, const Eigen::Vector2d& direction);

} // namespace synthetic
} // namespace morphreg
