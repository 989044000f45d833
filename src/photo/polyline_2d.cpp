// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/photo/polyline_2d.h>

#include <algorithm>
#include <limits>

namespace morphreg
{
Polyline2d::Polyline2d (Eigen::Matrix2Xd points) : points_ (std::move (points))
{
  if (points_.cols () < 2)
    throw InvalidInputError ("Polyline2d: " + std::to_string (points_.cols ()) + " points; at least 2 are needed");
  if (!points_.allFinite ())
    throw InvalidInputError ("Polyline2d: non-finite coordinates");
}

Eigen::Vector2d
Polyline2d::closestPoint (const Eigen::Vector2d& query) const
{
  Eigen::Vector2d best = points_.col (0);
  double best_distance = std::numeric_limits<double>::infinity ();
  for (Eigen::Index k = 0; k + 1 < points_.cols (); ++k) {
    const Eigen::Vector2d a = points_.col (k);
    const Eigen::Vector2d edge = points_.col (k + 1) - a;
    const double length2 = edge.squaredNorm ();
    const double t = length2 > 0.0 ? std::clamp ((query - a).dot (edge) / length2, 0.0, 1.0) : 0.0;
    const Eigen::Vector2d candidate = a + t * edge;
    const double distance = (candidate - query).squaredNorm ();
    if (distance < best_distance) {
      best_distance = distance;
      best = candidate;
    }
  }
  return best;
}
bool
Polyline2d::isEnd (const Eigen::Vector2d& point) const
{
  constexpr double kTolerance = 1e-12;
  return (point - points_.col (0)).norm () <= kTolerance ||
         (point - points_.col (points_.cols () - 1)).norm () <= kTolerance;
}
} // namespace morphreg
