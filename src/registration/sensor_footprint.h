// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Private to the library: what a one-view scan covers as its sensor sees it, for the global start of face-only
// and depth-camera scans (global_alignment.cpp).
#include <Eigen/Core>

#include <vector>

namespace morphreg
{
namespace detail
{
/** The outline of a scan seen along a view direction: an occupancy image of its points projected onto the plane
 *  across that direction (cells of a given edge, each point marking its cell and the 8 around it), so that the part
 *  of a posed model lying in front of or behind the scan can be told from the part beside it. */
class SensorFootprint
{
public:
  /** The footprint of \a points (3 x N, N >= 1) seen along the unit vector \a towards (scan to sensor), in cells
   *  of edge \a cell (mm). */
  SensorFootprint (const Eigen::Matrix3Xd& points, const Eigen::Vector3d& towards, double cell);

  /** Whether \a point projects into the scan's outline. */
  bool
  covers (const Eigen::Vector3d& point) const;

private:
  /** \a point's coordinates across the view direction. */
  Eigen::Vector2d
  across (const Eigen::Vector3d& point) const
  {
    return {u_.dot (point), v_.dot (point)};
  }

  double cell_;
  Eigen::Vector3d u_, v_;
  Eigen::Vector2d low_;
  Eigen::Array2i size_;
  std::vector<char> occupied_;
};

} // namespace detail
} // namespace morphreg
