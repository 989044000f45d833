// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/photo/profile_view.h>

namespace morphreg
{
ProfileView::ProfileView (int width, int height, std::vector<Eigen::Vector2d> silhouette,
                          const Eigen::Vector2d& nose_tip, const std::string& source)
  : normalisation_ (width, height, nose_tip, source), silhouette_ (std::move (silhouette))
{
  if (silhouette_.size () < kMinimumSilhouettePoints)
    throw InvalidInputError (source + ": the silhouette polyline has " + std::to_string (silhouette_.size ()) +
                             " points; it needs at least " + std::to_string (kMinimumSilhouettePoints) +
                             " (trace the outline from the neck over the face)");
  bool distinct = false;
  for (size_t k = 0; k < silhouette_.size (); ++k) {
    requireFinitePixel (silhouette_[k], source + ": silhouette point " + std::to_string (k));
    distinct = distinct || silhouette_[k] != silhouette_.front ();
  }
  if (!distinct)
    throw InvalidInputError (source + ": all silhouette points coincide");
  requireFacingRight (nose_tip, source);
}

void
ProfileView::requireFacingRight (const Eigen::Vector2d& nose_tip, const std::string& source) const
{
  double mean_x = 0.0;
  for (const Eigen::Vector2d& point : silhouette_)
    mean_x += point.x () / static_cast<double> (silhouette_.size ());
  if (nose_tip.x () < mean_x)
    throw InvalidInputError (source + ": the face looks left (the nose tip, x = " + std::to_string (nose_tip.x ()) +
                             " px, lies left of the silhouette's mean x = " + std::to_string (mean_x) +
                             " px); mirror the photo so that the face looks right, then annotate it");
}

Eigen::Matrix2Xd
ProfileView::normalisedSilhouette () const
{
  Eigen::Matrix2Xd points (2, silhouette_.size ());
  for (size_t k = 0; k < silhouette_.size (); ++k)
    points.col (static_cast<Eigen::Index> (k)) = normalisation_.normalise (silhouette_[k]);
  return points;
}
} // namespace morphreg
