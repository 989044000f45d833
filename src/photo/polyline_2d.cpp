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
  double area = 0.0;
  for (Eigen::Index k = 0; k < points_.cols (); ++k) {
    const Eigen::Vector2d a = points_.col (k), b = points_.col ((k + 1) % points_.cols ());
    area += a.x () * b.y () - b.x () * a.y ();
  }
  orientation_ = area < 0.0 ? -1.0 : 1.0;
}

Polyline2d::Projection
Polyline2d::project (const Eigen::Vector2d& query) const
{
  Projection best{points_.col (0), 0, 0.0};
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
      best = {candidate, k, t};
    }
  }
  return best;
}

Eigen::Vector2d
Polyline2d::outwardNormal (Eigen::Index segment) const
{
  Eigen::Vector2d edge = Eigen::Vector2d::Zero ();
  // A repeated point makes an empty segment: take the direction of the nearest segment that has one.
  for (Eigen::Index offset = 0; edge.squaredNorm () == 0.0 && offset < points_.cols (); ++offset)
    for (const Eigen::Index k : {segment + offset, segment - offset})
      if (k >= 0 && k + 1 < points_.cols () && edge.squaredNorm () == 0.0)
        edge = points_.col (k + 1) - points_.col (k);
  // In pixel coordinates (y down) a positive area runs clockwise on screen: the outside is to the left of travel.
  return orientation_ * Eigen::Vector2d (edge.y (), -edge.x ()).normalized ();
}

bool
Polyline2d::isEnd (const Eigen::Vector2d& point) const
{
  constexpr double kTolerance = 1e-12;
  return (point - points_.col (0)).norm () <= kTolerance ||
         (point - points_.col (points_.cols () - 1)).norm () <= kTolerance;
}
} // namespace morphreg
