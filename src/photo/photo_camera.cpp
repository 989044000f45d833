// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/photo/photo_camera.h>

#include <Eigen/LU>
#include <Eigen/QR>

#include <cmath>

namespace morphreg
{
namespace
{
/** Throws InvalidInputError naming \a source unless \a K is a pinhole intrinsic matrix. */
void
requireIntrinsics (const Eigen::Matrix3d& K, const std::string& source)
{
  if (!K.allFinite () || K (1, 0) != 0.0 || K (2, 0) != 0.0 || K (2, 1) != 0.0 || K (2, 2) != 1.0)
    throw InvalidInputError (source + ": K must be finite, upper triangular, with the last row (0, 0, 1)");
  if (!(K (0, 0) > 0.0) || !(K (1, 1) > 0.0))
    throw InvalidInputError (source + ": K's focal lengths must be > 0 pixels, got " + std::to_string (K (0, 0)) +
                             " and " + std::to_string (K (1, 1)));
}

/** Throws InvalidInputError naming \a source unless \a R is a finite rotation. */
void
requireRotation (const Eigen::Matrix3d& R, const std::string& source)
{
  if (!R.allFinite () || !(R * R.transpose ()).isApprox (Eigen::Matrix3d::Identity (), 1e-6) ||
      !(R.determinant () > 0.0))
    throw InvalidInputError (source + ": R is not a rotation (orthonormal with determinant +1)");
}
} // namespace

PhotoCamera
PhotoCamera::perspective (const Eigen::Matrix3d& K, const Eigen::Matrix3d& R, const Eigen::Vector3d& t,
                          const std::string& source)
{
  requireIntrinsics (K, source);
  requireRotation (R, source);
  if (!t.allFinite ())
    throw InvalidInputError (source + ": t is not finite");
  return PhotoCamera (true, K, R, t);
}

PhotoCamera
PhotoCamera::fromProjection (const Eigen::Matrix<double, 3, 4>& P, const std::string& source)
{
  if (!P.allFinite ())
    throw InvalidInputError (source + ": P is not finite");
  Eigen::Matrix<double, 3, 4> projection = P;
  const double determinant = P.leftCols<3> ().determinant ();
  if (!(std::abs (determinant) > 1e-12 * std::pow (P.leftCols<3> ().norm (), 3)))
    throw InvalidInputError (source + ": P's left 3 x 3 block is singular (not a pinhole camera)");
  if (determinant < 0.0)
    projection = -projection; // the same camera; K R then has a positive determinant
  // RQ decomposition M = K R through the QR decomposition of the reversed, transposed M.
  Eigen::Matrix3d reverse;
  reverse << 0, 0, 1, 0, 1, 0, 1, 0, 0;
  const Eigen::HouseholderQR<Eigen::Matrix3d> qr ((reverse * projection.leftCols<3> ()).transpose ());
  const Eigen::Matrix3d upper = qr.matrixQR ().triangularView<Eigen::Upper> ();
  Eigen::Matrix3d K = reverse * upper.transpose () * reverse;
  Eigen::Matrix3d R = reverse * Eigen::Matrix3d (qr.householderQ ()).transpose ();
  const Eigen::Vector3d signs = K.diagonal ().array ().sign ();
  K = K * signs.asDiagonal ();
  R = signs.asDiagonal () * R;
  const double scale = K (2, 2);
  K /= scale;
  K (1, 0) = K (2, 0) = K (2, 1) = 0.0;
  K (2, 2) = 1.0;
  const Eigen::Vector3d t = K.inverse () * projection.col (3) / scale;
  return perspective (K, R, t, source);
}

PhotoCamera
PhotoCamera::orthographic (const Eigen::Matrix3d& R, double pixels_per_unit, const Eigen::Vector2d& principal)
{
  requireRotation (R, "PhotoCamera::orthographic");
  if (!(pixels_per_unit > 0.0) || !std::isfinite (pixels_per_unit) || !principal.allFinite ())
    throw InvalidInputError ("PhotoCamera::orthographic: the scale must be finite and > 0 and the principal point "
                             "finite");
  Eigen::Matrix3d K = Eigen::Matrix3d::Identity ();
  K (0, 0) = K (1, 1) = pixels_per_unit;
  K.topRightCorner<2, 1> () = principal;
  return PhotoCamera (false, K, R, Eigen::Vector3d::Zero ());
}

Eigen::Vector2d
PhotoCamera::project (const Eigen::Vector3d& point) const
{
  const Eigen::Vector3d c = toCamera (point);
  if (!perspective_)
    return (intrinsics_ * Eigen::Vector3d (c.x (), c.y (), 1.0)).head<2> ();
  const Eigen::Vector3d h = intrinsics_ * c;
  return h.head<2> () / h.z ();
}

Eigen::Matrix<double, 2, 3>
PhotoCamera::jacobian (const Eigen::Vector3d& point) const
{
  if (!perspective_)
    return intrinsics_.topLeftCorner<2, 2> () * rotation_.topRows<2> ();
  const Eigen::Vector3d h = intrinsics_ * toCamera (point);
  Eigen::Matrix<double, 2, 3> divide;
  divide << 1.0 / h.z (), 0.0, -h.x () / (h.z () * h.z ()), 0.0, 1.0 / h.z (), -h.y () / (h.z () * h.z ());
  return divide * intrinsics_ * rotation_;
}

Eigen::Vector3d
PhotoCamera::towardsCamera (const Eigen::Vector3d& point) const
{
  if (!perspective_)
    return -rotation_.row (2).transpose ();
  return (centre () - point).normalized ();
}

double
PhotoCamera::pixelsPerUnit (const Eigen::Vector3d& point) const
{
  const double focal = std::sqrt (intrinsics_ (0, 0) * intrinsics_ (1, 1));
  return perspective_ ? focal / toCamera (point).z () : focal;
}
} // namespace morphreg
