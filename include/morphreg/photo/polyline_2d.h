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

  /** \brief The point of the polyline closest to \a query.
   *  \param[in] query the point
   *  \return the closest point on any segment
   */
  Eigen::Vector2d
  closestPoint (const Eigen::Vector2d& query) const;

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
};
} // namespace morphreg
