// SPDX-License-Identifier: BSD-3-Clause
#include "sensor_footprint.h"

#include <Eigen/Geometry>

namespace morphreg
{
namespace detail
{
SensorFootprint::SensorFootprint (const Eigen::Matrix3Xd& points, const Eigen::Vector3d& towards, double cell)
  : cell_ (cell), u_ (towards.unitOrthogonal ()), v_ (towards.cross (u_))
{
  Eigen::Matrix2Xd projected (2, points.cols ());
  for (Eigen::Index i = 0; i < points.cols (); ++i)
    projected.col (i) = across (points.col (i));
  // One empty cell on each side beyond the marked border, so that marking the 8 neighbours stays inside.
  low_ = projected.rowwise ().minCoeff ().array () - 2.0 * cell;
  size_ = ((projected.rowwise ().maxCoeff ().array () + 2.0 * cell - low_.array ()) / cell).ceil ().cast<int> ();
  occupied_.assign (static_cast<size_t> (size_[0]) * static_cast<size_t> (size_[1]), 0);
  for (Eigen::Index i = 0; i < points.cols (); ++i) {
    const Eigen::Array2i c = ((projected.col (i) - low_).array () / cell).cast<int> ();
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        occupied_[static_cast<size_t> (c[1] + dy) * static_cast<size_t> (size_[0]) + static_cast<size_t> (c[0] + dx)] =
            1;
  }
}

bool
SensorFootprint::covers (const Eigen::Vector3d& point) const
{
  const Eigen::Array2d f = (across (point) - low_).array () / cell_;
  if ((f < 0.0).any () || (f >= size_.cast<double> ()).any ())
    return false;
  return occupied_[static_cast<size_t> (f[1]) * static_cast<size_t> (size_[0]) + static_cast<size_t> (f[0])] != 0;
}

} // namespace detail
} // namespace morphreg
