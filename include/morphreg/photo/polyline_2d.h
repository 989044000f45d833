// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file polyline_2d.h
 *  \brief Closest points on a 2D polyline (the profile silhouette of the two-view fit).
 */
#include <Eigen/Core>

namespace morphreg
{
/** \brief An open polyline through the columns of a 2 x K matrix (K >= 2), queried for the closest point on its
 *  segments. Brute force over the segments: silhouettes have a few hundred points.
 */
class Polyline2d
{
public:
  /** \brief Throws InvalidInputError for fewer than 2 points or non-finite coordinates.
   *  \param[in] points the vertices in order, one per column
   */
  explicit Polyline2d (Eigen::Matrix2Xd points);

  /** \brief Where a query lands on the polyline. */
  struct Projection
  {
    Eigen::Vector2d point; ///< the closest point
    Eigen::Index segment;  ///< the segment it lies on (from point segment to point segment + 1)
    double along;          ///< its position on the segment, 0 at the segment's start, 1 at its end
  };

  /** \brief The point of the polyline closest to \a query.
   *  \param[in] query the point
   *  \return the closest point on any segment
   */
  Eigen::Vector2d
  closestPoint (const Eigen::Vector2d& query) const
  {
    return project (query).point;
  }

  /** \brief The point of the polyline closest to \a query, with its segment.
   *  \param[in] query the point
   *  \return the closest point, its segment and its position on it
   */
  Projection
  project (const Eigen::Vector2d& query) const;

  /** \brief The unit normal of segment \a segment on the side away from the region the polyline bounds when it is
   *  closed by a straight line from its last point to its first (the head, for an outline traced around it).
   *  \param[in] segment a segment index (0 .. points - 2)
   *  \return the outward unit normal
   */
  Eigen::Vector2d
  outwardNormal (Eigen::Index segment) const;

  /** \brief Whether \a point (a closestPoint result) is one of the polyline's two ends: a query beyond the traced
   *  part of a silhouette lands there, and says nothing about where the outline goes.
   *  \param[in] point a result of closestPoint()
   *  \return true at either end
   */
  bool
  isEnd (const Eigen::Vector2d& point) const;

  /** \brief The polyline's vertices.
   *  \return 2 x K, in order
   */
  const Eigen::Matrix2Xd&
  points () const

  {
    return points_;
  }

private:
  Eigen::Matrix2Xd points_;
  double orientation_ = 1.0; ///< +1 or -1: the sign of the closed polyline's area, which side is outside
};
} // namespace morphreg
