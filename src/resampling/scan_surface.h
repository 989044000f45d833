// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Private to the library: the scan's surface as ScanResampler's rays see it, a triangle mesh (Intel Embree's ray
// tracing) or a point cloud (Gaussian-weighted local planes over a grid of its points).
#include <morphreg/mesh/triangle_mesh.h>

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace morphreg
{
namespace detail
{
/** The scan's surface: where a vertex's normal line first meets it. */
class ScanSurface
{
public:
  virtual ~ScanSurface () = default;

  /** The intersection of the line origin + t * direction (unit) with the surface, |t| <= max_distance, nearest to
   *  \a origin among those whose surface normal n satisfies n . direction >= min_cos (|n . direction| where the
   *  surface's normals are unoriented); false if there is none. */
  virtual bool
  intersect (const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double max_distance, double min_cos,
             Eigen::Vector3d& hit) const = 0;

  /** The surface's points (mesh vertices or cloud points), for its size and extent. */
  virtual const Eigen::Matrix3Xd&
  points () const = 0;

  /** Whether intersect() may be called from several threads at once. */
  virtual bool
  threadSafe () const = 0;
};

/** A triangulated scan; rays cast through Intel Embree. */
std::unique_ptr<ScanSurface>
makeMeshSurface (const TriangleMesh& scan);

/** A point cloud scan (3 x N finite points; normals 3 x N with NaN where unknown, or empty); the local plane of the
 *  \a neighbours nearest points stands for the surface. */
std::unique_ptr<ScanSurface>
makeCloudSurface (Eigen::Matrix3Xd points, Eigen::Matrix3Xd normals, int neighbours);

/** Per point of a cloud (3 x N): its local spacing, the distance to its 4th nearest other point. */
std::vector<double>
localSpacings (const Eigen::Matrix3Xd& points);

/** Where the spacing is the median of \a spacings, the usual distance of a point's \a neighbours-th nearest
 *  neighbour: sqrt(k) / 2 spacings. The cloud surface searches through a grid of cells half this size. */
double
usualKthDistance (const std::vector<double>& spacings, int neighbours);
} // namespace detail
} // namespace morphreg
