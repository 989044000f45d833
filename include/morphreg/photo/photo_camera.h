// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file photo_camera.h
 *  \brief The camera of one photo in a multi-view fit: a pinhole (perspective) camera x ~ K [R | t] X, or an
 *  orthographic one (the frontal and profile photos of docs/method.md, "Fitting to photographs"). Pixels: x right,
 *  y down, origin at the image's top-left corner; camera coordinates: x right, y down, z forward (OpenCV's).
 */
#include <Eigen/Core>

#include <string>

namespace morphreg
{
/** \brief Maps points of the views' common (world) frame to pixels, with the derivatives a Gauss-Newton fit needs.
 *  Camera coordinates are c = R X + t. A perspective camera gives the pixel (K c) / c_z; an orthographic one
 *  K (c_x, c_y, 1), so that K's focal lengths are pixels per world unit and its last column the pixel of the
 *  camera axis.
 */
class PhotoCamera
{
public:
  /** \brief A pinhole camera. Throws InvalidInputError naming \a source unless \a K is upper triangular with a last
   *  row (0, 0, 1) and positive focal lengths, \a R is a rotation (orthonormal within 1e-6, determinant +1) and
   *  everything is finite.
   *  \param[in] K the intrinsics (pixels)
   *  \param[in] R the rotation from the world frame into the camera's
   *  \param[in] t the world origin in camera coordinates
   *  \param[in] source the camera's file or origin, for messages
   *  \return the camera
   */
  static PhotoCamera
  perspective (const Eigen::Matrix3d& K, const Eigen::Matrix3d& R, const Eigen::Vector3d& t, const std::string& source);

  /** \brief The pinhole camera of a 3 x 4 projection matrix P ~ K [R | t] (RQ decomposition, K with positive
   *  diagonal). Throws InvalidInputError naming \a source for a non-finite P or one whose left 3 x 3 block is
   *  singular.
   *  \param[in] P the projection matrix (any scale)
   *  \param[in] source the camera's file or origin, for messages
   *  \return the camera
   */
  static PhotoCamera
  fromProjection (const Eigen::Matrix<double, 3, 4>& P, const std::string& source);

  /** \brief An orthographic camera: pixel = principal + pixels_per_unit (c_x, c_y) with c = R X (no translation:
   *  \a principal is the pixel of the world origin).
   *  \param[in] R the rotation from the world frame into the camera's
   *  \param[in] pixels_per_unit pixels per world unit (> 0)
   *  \param[in] principal the pixel of the world origin
   *  \return the camera
   */
  static PhotoCamera
  orthographic (const Eigen::Matrix3d& R, double pixels_per_unit, const Eigen::Vector2d& principal);

  /** \brief Whether the camera is a pinhole one.
   *  \return true for perspective, false for orthographic
   */
  bool
  isPerspective () const
  {
    return perspective_;
  }

  /** \brief c = R X + t.
   *  \param[in] point a world point
   *  \return the point in camera coordinates
   */
  Eigen::Vector3d
  toCamera (const Eigen::Vector3d& point) const
  {
    return rotation_ * point + translation_;
  }

  /** \brief The pixel of \a point.
   *  \param[in] point a world point (in front of a perspective camera)
   *  \return its pixel
   */
  Eigen::Vector2d
  project (const Eigen::Vector3d& point) const;

  /** \brief The 2 x 3 derivative of project() at \a point with respect to the world point.
   *  \param[in] point a world point
   *  \return d pixel / d X
   */
  Eigen::Matrix<double, 2, 3>
  jacobian (const Eigen::Vector3d& point) const;

  /** \brief The unit vector from \a point towards the camera (the reverse of the viewing ray through it).
   *  \param[in] point a world point
   *  \return the direction to the camera centre, or against the orthographic viewing direction
   */
  Eigen::Vector3d
  towardsCamera (const Eigen::Vector3d& point) const;

  /** \brief Pixels per world unit at \a point (f / depth, or the orthographic scale), the geometric mean of the two
   *  axes: what turns a pixel residual into a world distance.
   *  \param[in] point a world point
   *  \return pixels per world unit
   */
  double
  pixelsPerUnit (const Eigen::Vector3d& point) const;

  /** \brief K.
   *  \return the intrinsics
   */
  const Eigen::Matrix3d&
  intrinsics () const
  {
    return intrinsics_;
  }

  /** \brief R.
   *  \return the rotation from the world frame into the camera's
   */
  const Eigen::Matrix3d&
  rotation () const
  {
    return rotation_;
  }

  /** \brief t.
   *  \return the world origin in camera coordinates
   */
  const Eigen::Vector3d&
  translation () const
  {
    return translation_;
  }

  /** \brief The camera centre -R^T t in the world frame (perspective cameras).
   *  \return the centre
   */
  Eigen::Vector3d
  centre () const
  {
    return -rotation_.transpose () * translation_;
  }

private:
  PhotoCamera (bool perspective, const Eigen::Matrix3d& K, const Eigen::Matrix3d& R, const Eigen::Vector3d& t)
    : perspective_ (perspective), intrinsics_ (K), rotation_ (R), translation_ (t)
  {}

  bool perspective_;
  Eigen::Matrix3d intrinsics_;
  Eigen::Matrix3d rotation_;
  Eigen::Vector3d translation_;
};
} // namespace morphreg
