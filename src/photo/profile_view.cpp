#include <morphreg/common/error.h>
#include <morphreg/photo/profile_view.h>

namespace morphreg
{
ProfileView::ProfileView (int width, int height, std::vector<Eigen::Vector2d> silhouette,
                          const Eigen::Vector2d& nose_tip, const std::string& source)
  : normalisation_ (width, height, nose_tip, source), silhouette_ (std::move (silhouette))
{
  if (silhouette_.size () < 2)
    throw InvalidInputError (source + ": the silhouette polyline has " + std::to_string (silhouette_.size ()) +
                             " points; it needs at least 2");
  bool distinct = false;
  for (size_t k = 0; k < silhouette_.size (); ++k) {
    requireFinitePixel (silhouette_[k], source + ": silhouette point " + std::to_string (k));
    distinct = distinct || silhouette_[k] != silhouette_.front ();
  }
  if (!distinct)
    throw InvalidInputError (source + ": all silhouette points coincide");
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
