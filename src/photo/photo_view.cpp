// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/photo/photo_view.h>
#include <morphreg/photo/polyline_2d.h>

#include <cmath>

namespace morphreg
{
PhotoView::PhotoView (int width, int height, LandmarkPixels landmarks, std::string source)
  : width_ (width), height_ (height), landmarks_ (std::move (landmarks)), source_ (std::move (source))
{
  if (width_ <= 0 || height_ <= 0)
    throw InvalidInputError (source_ + ": the image size " + std::to_string (width_) + " x " +
                             std::to_string (height_) + " px must be positive");
  for (const auto& landmark : landmarks_) {
    requireKnownLandmarkId (landmark.first, source_);
    requireFinitePixel (landmark.second, source_ + ": landmark '" + landmark.first + "'");
  }
}

void
PhotoView::setOutline (std::vector<Eigen::Vector2d> outline, const std::optional<Eigen::Vector2d>& hairline)
{
  if (outline.size () < kMinimumOutlinePoints)
    throw InvalidInputError (source_ + ": the outline has " + std::to_string (outline.size ()) +
                             " points; it needs at least " + std::to_string (kMinimumOutlinePoints) +
                             " (trace the head's outline along the face and around the hair)");
  bool distinct = false;
  for (size_t k = 0; k < outline.size (); ++k) {
    requireFinitePixel (outline[k], source_ + ": outline point " + std::to_string (k));
    distinct = distinct || outline[k] != outline.front ();
  }
  if (!distinct)
    throw InvalidInputError (source_ + ": all outline points coincide");
  if (hairline) {
    requireFinitePixel (*hairline, source_ + ": the hairline mark");
    Eigen::Matrix2Xd points (2, outline.size ());
    for (size_t k = 0; k < outline.size (); ++k)
      points.col (static_cast<Eigen::Index> (k)) = outline[k];
    const double distance = (Polyline2d (points).closestPoint (*hairline) - *hairline).norm ();
    if (distance > 0.05 * std::max (width_, height_))
      throw InvalidInputError (source_ + ": the hairline mark lies " + std::to_string (distance) +
                               " px from the outline; mark it on the outline where the hair begins");
  }
  outline_ = std::move (outline);
  hairline_ = hairline;
}

void
PhotoView::setFocalLength35mm (double millimetres)
{
  if (!(millimetres > 0.0) || !std::isfinite (millimetres))
    throw InvalidInputError (source_ + ": the 35 mm focal length must be finite and > 0, got " +
                             std::to_string (millimetres));
  focal_35mm_ = millimetres;
}

PhotoCamera
frontalCamera (const PhotoNormalisation& frame)
{
  return PhotoCamera::orthographic (Eigen::Vector3d (1.0, -1.0, -1.0).asDiagonal ().toDenseMatrix (),
                                    frame.longerSide (), frame.noseTip ());
}

PhotoCamera
profileCamera (const PhotoNormalisation& frame)
{
  Eigen::Matrix3d R;
  R << 0, 0, 1, 0, -1, 0, 1, 0, 0; // image x = +Z (the face to the right), image y = -Y, looking along +X
  return PhotoCamera::orthographic (R, frame.longerSide (), frame.noseTip ());
}

PhotoView
frontalPhotoView (const FrontalView& frontal)
{
  const PhotoNormalisation& n = frontal.normalisation ();
  PhotoView view (n.width (), n.height (), frontal.landmarks (), "the frontal photo");
  view.setCamera (frontalCamera (n));
  return view;
}

PhotoView
profilePhotoView (const ProfileView& profile)
{
  const PhotoNormalisation& n = profile.normalisation ();
  PhotoView view (n.width (), n.height (), {}, "the profile photo");
  view.setOutline (profile.silhouette ());
  view.setCamera (profileCamera (n));
  return view;
}

std::vector<PhotoView>
orthographicPairViews (const ProfileView& profile, const FrontalView* frontal)
{
  std::vector<PhotoView> views{profilePhotoView (profile)};
  if (frontal)
    views.push_back (frontalPhotoView (*frontal));
  return views;
}
} // namespace morphreg
