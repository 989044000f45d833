// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file photo_view.h
 *  \brief One photo of a multi-view fit (docs/method.md, "Fitting to photographs"): its size, the landmarks marked
 *  on it, the head's outline traced on it (optional, with an optional mark where the hair begins) and its camera
 *  (optional: a missing one is estimated from the landmarks).
 */
#include <morphreg/common/landmarks.h>
#include <morphreg/photo/frontal_view.h>
#include <morphreg/photo/photo_camera.h>
#include <morphreg/photo/profile_view.h>

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief An annotated photo. Landmarks use the ids of docs/landmarks.md and iBUG-68 (ibug68_00 ..); the outline
 *  points (isOutlineLandmarkId: jaw, chin, neck, head contour) constrain where the model's outline passes, the
 *  others fix model vertices. The traced outline is an open polyline along the head's outline (hair included): the
 *  model lies on it along the face (forehead to chin) and inside it elsewhere.
 */
class PhotoView
{
public:
  /** \brief Throws InvalidInputError naming \a source for a non-positive image size, an unknown landmark id or a
   *  non-finite pixel.
   *  \param[in] width the image width in pixels
   *  \param[in] height the image height in pixels
   *  \param[in] landmarks the marked landmarks in pixels (may be empty when an outline is given)
   *  \param[in] source the photo or annotation, for messages
   */
  PhotoView (int width, int height, LandmarkPixels landmarks, std::string source);

  /** \brief The head's outline and, optionally, the point of it where the hair begins above the forehead (the
   *  outline beyond it, away from the face, is hair). Throws InvalidInputError naming the view for fewer than
   *  kMinimumOutlinePoints points, non-finite or all coincident points, or a hairline farther than 5 % of the
   *  image's longer side from the outline.
   *  \param[in] outline the traced outline in pixels, in order along it
   *  \param[in] hairline where the hair begins, or none (the fit finds it)
   */
  void
  setOutline (std::vector<Eigen::Vector2d> outline, const std::optional<Eigen::Vector2d>& hairline = std::nullopt);

  /** \brief The photo's camera, used as it is (in the frame shared by every view with a camera).
   *  \param[in] camera the camera
   */
  void
  setCamera (const PhotoCamera& camera)
  {
    camera_ = camera;
  }

  /** \brief The lens's 35 mm equivalent focal length (EXIF), used when the camera is estimated (> 0).
   *  \param[in] millimetres the focal length in 35 mm terms
   */
  void
  setFocalLength35mm (double millimetres);

  /** \brief The image width.
   *  \return pixels
   */
  int
  width () const
  {
    return width_;
  }

  /** \brief The image height.
   *  \return pixels
   */
  int
  height () const
  {
    return height_;
  }

  /** \brief The marked landmarks.
   *  \return id -> pixel
   */
  const LandmarkPixels&
  landmarks () const
  {
    return landmarks_;
  }

  /** \brief The traced outline (empty if none was given).
   *  \return the points in order, pixels
   */
  const std::vector<Eigen::Vector2d>&
  outline () const
  {
    return outline_;
  }

  /** \brief Where the hair begins on the outline, if the user marked it.
   *  \return the pixel, or none
   */
  const std::optional<Eigen::Vector2d>&
  hairline () const
  {
    return hairline_;
  }

  /** \brief The given camera, if any.
   *  \return the camera, or none
   */
  const std::optional<PhotoCamera>&
  camera () const
  {
    return camera_;
  }

  /** \brief The EXIF focal length in 35 mm terms, or 0.
   *  \return millimetres
   */
  double
  focalLength35mm () const
  {
    return focal_35mm_;
  }

  /** \brief The photo's name for messages and reports.
   *  \return the source given to the constructor
   */
  const std::string&
  source () const
  {
    return source_;
  }

  /** \brief The fewest outline points a view takes (a traced outline has many more). */
  static constexpr std::size_t kMinimumOutlinePoints = 10;

private:
  int width_;
  int height_;
  LandmarkPixels landmarks_;
  std::string source_;
  std::vector<Eigen::Vector2d> outline_;
  std::optional<Eigen::Vector2d> hairline_;
  std::optional<PhotoCamera> camera_;
  double focal_35mm_ = 0.0;
};

/** \brief The orthographic camera of the pair's frontal photo: looking along -Z of the normalised frame, pixel =
 *  nose tip + longer side (X, -Y).
 *  \param[in] frame the photo's normalisation
 *  \return the camera
 */
PhotoCamera
frontalCamera (const PhotoNormalisation& frame);

/** \brief The orthographic camera of the pair's profile photo: looking along +X of the normalised frame, pixel =
 *  nose tip + longer side (Z, -Y) (the face to the image's right).
 *  \param[in] frame the photo's normalisation
 *  \return the camera
 */
PhotoCamera
profileCamera (const PhotoNormalisation& frame);

/** \brief The frontal photo of the orthographic pair as a view: its landmarks and the orthographic camera looking
 *  along -Z of the normalised frame (PhotoNormalisation: the world frame of the pair, the nose tip at its origin).
 *  \param[in] frontal the frontal annotation
 *  \return the view
 */
PhotoView
frontalPhotoView (const FrontalView& frontal);

/** \brief The profile photo of the orthographic pair as a view: its silhouette as the outline and the orthographic
 *  camera looking along +X of the normalised frame (the face to the image's right). Its nose tip centres the frame
 *  and is no landmark.
 *  \param[in] profile the profile annotation
 *  \return the view
 */
PhotoView
profilePhotoView (const ProfileView& profile);

/** \brief The orthographic pair as views: the profile photo, then the frontal photo when given.
 *  \param[in] profile the profile annotation
 *  \param[in] frontal the frontal annotation, or null
 *  \return the views
 */
std::vector<PhotoView>
orthographicPairViews (const ProfileView& profile, const FrontalView* frontal);
} // namespace morphreg
