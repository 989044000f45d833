// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file camera_estimation.h
 *  \brief The camera of a photo that came without one: its pose from landmarks whose 3D positions are known
 *  (perspective-n-point), its focal length given (EXIF) or searched within a range, the principal point at the
 *  image's centre.
 */
#include <morphreg/photo/photo_camera.h>

#include <Eigen/Core>

#include <string>

namespace morphreg
{
/** \brief The focal lengths (pixels) a camera is searched over; min == max fixes it. */
struct FocalRange
{
  double min = 0.0;   ///< pixels
  double max = 0.0;   ///< pixels
  std::string source; ///< where the range came from, for the report ("EXIF 35 mm focal length 50 mm", ...)

  /** \brief The range of a photo of \a width x \a height pixels: from \a focal_35mm (EXIF) when it is given,
   *  else 35 mm equivalents of kMin35mm to kMax35mm (phone wide angles to long portrait lenses).
   *  \param[in] width the image width (px)
   *  \param[in] height the image height (px)
   *  \param[in] focal_35mm the EXIF focal length in 35 mm terms, or <= 0 for none
   *  \return the range
   */
  static FocalRange
  forImage (int width, int height, double focal_35mm);

  static constexpr double kMin35mm = 20.0;  ///< mm, 35 mm equivalent: the shortest focal length searched
  static constexpr double kMax35mm = 300.0; ///< mm: the longest
};

/** \brief A camera found from landmarks, and how well it explains them. */
struct CameraEstimate
{
  PhotoCamera camera;      ///< the camera
  double rms_pixels = 0.0; ///< the landmarks' reprojection RMS (px)
};

/** \brief The pose of a camera of intrinsics \a K that best projects \a points onto \a pixels: a weak-perspective
 *  start from an affine fit, then Gauss-Newton on the reprojection error. Throws as estimateCamera.
 *  \param[in] points the landmarks' 3D positions (world frame)
 *  \param[in] pixels their marked pixels, in the same order
 *  \param[in] K the camera's intrinsics
 *  \param[in] source the photo, for messages
 *  \return the camera and its reprojection RMS
 */
CameraEstimate
estimatePose (const Eigen::Matrix3Xd& points, const Eigen::Matrix2Xd& pixels, const Eigen::Matrix3d& K,
              const std::string& source);

/** \brief The pinhole camera (square pixels, no skew, principal point at the image centre, focal length within
 *  \a focal) that best projects \a points onto \a pixels: a weak-perspective start from an affine fit, Gauss-Newton
 *  on the reprojection error over the pose, the focal length searched on a log grid and refined. Throws
 *  InvalidInputError naming \a source for fewer than 6 points, points that are coplanar (they fix no pose), a
 *  non-positive range or an image size that is not positive.
 *  \param[in] points the landmarks' 3D positions (world frame)
 *  \param[in] pixels their marked pixels, in the same order
 *  \param[in] width the image width (px)
 *  \param[in] height the image height (px)
 *  \param[in] focal the focal lengths searched (pixels)
 *  \param[in] source the photo, for messages
 *  \return the camera and its reprojection RMS
 */
CameraEstimate
estimateCamera (const Eigen::Matrix3Xd& points, const Eigen::Matrix2Xd& pixels, int width, int height,
                const FocalRange& focal, const std::string& source);
} // namespace morphreg
