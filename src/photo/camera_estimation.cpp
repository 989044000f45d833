// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/photo/camera_estimation.h>
#include <morphreg/photo/jpeg_exif.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <cmath>
#include <limits>

namespace morphreg
{
namespace
{
constexpr int kFocalGrid = 16;        ///< log-spaced focal lengths tried over the range
constexpr int kFocalRefinements = 12; ///< golden-section steps around the best of them
constexpr int kPoseIterations = 30;   ///< Gauss-Newton steps of one pose

Eigen::Matrix3d
skew (const Eigen::Vector3d& v)
{
  Eigen::Matrix3d s;
  s << 0, -v.z (), v.y (), v.z (), 0, -v.x (), -v.y (), v.x (), 0;
  return s;
}

Eigen::Matrix3d
intrinsicsFor (double focal, int width, int height)
{
  Eigen::Matrix3d K = Eigen::Matrix3d::Identity ();
  K (0, 0) = K (1, 1) = focal;
  K (0, 2) = 0.5 * width;
  K (1, 2) = 0.5 * height;
  return K;
}

/** The pose (R, t) of a weak-perspective camera of focal length K(0,0) fitted to the points by an affine map. */
std::pair<Eigen::Matrix3d, Eigen::Vector3d>
weakPerspectivePose (const Eigen::Matrix3Xd& points, const Eigen::Matrix2Xd& pixels, const Eigen::Matrix3d& K)
{
  Eigen::MatrixXd design (points.cols (), 4);
  design.leftCols<3> () = points.transpose ();
  design.col (3).setOnes ();
  const Eigen::Matrix<double, 4, 2> affine = design.colPivHouseholderQr ().solve (pixels.transpose ());
  const Eigen::Matrix<double, 2, 3> A = affine.topRows<3> ().transpose ();
  const double scale = 0.5 * (A.row (0).norm () + A.row (1).norm ());
  Eigen::Matrix3d R;
  R.row (0) = A.row (0).normalized ();
  R.row (1) = (A.row (1) - A.row (1).dot (R.row (0)) * R.row (0)).normalized ();
  R.row (2) = R.row (0).cross (R.row (1));
  const Eigen::Vector3d centroid = points.rowwise ().mean ();
  const Eigen::Vector2d image_centroid = A * centroid + affine.row (3).transpose ();
  Eigen::Vector3d camera_centroid;
  camera_centroid.head<2> () = (image_centroid - K.topRightCorner<2, 1> ()) / scale;
  camera_centroid.z () = K (0, 0) / scale;
  return {R, camera_centroid - R * centroid};
}

/** Reprojection RMS (px) of the points through K [R | t]; infinity if one lies behind the camera. */
double
reprojectionRms (const Eigen::Matrix3Xd& points, const Eigen::Matrix2Xd& pixels, const Eigen::Matrix3d& K,
                 const Eigen::Matrix3d& R, const Eigen::Vector3d& t)
{
  double sum = 0.0;
  for (Eigen::Index i = 0; i < points.cols (); ++i) {
    const Eigen::Vector3d h = K * (R * points.col (i) + t);
    if (!(h.z () > 0.0))
      return std::numeric_limits<double>::infinity ();
    sum += (h.head<2> () / h.z () - pixels.col (i)).squaredNorm ();
  }
  return std::sqrt (sum / static_cast<double> (points.cols ()));
}

/** Gauss-Newton (Levenberg-Marquardt damped) on the reprojection error over the pose; returns the RMS. */
double
refinePose (const Eigen::Matrix3Xd& points, const Eigen::Matrix2Xd& pixels, const Eigen::Matrix3d& K,
            Eigen::Matrix3d& R, Eigen::Vector3d& t)
{
  double rms = reprojectionRms (points, pixels, K, R, t), damping = 1e-3;
  for (int it = 0; it < kPoseIterations && std::isfinite (rms); ++it) {
    Eigen::Matrix<double, 6, 6> hessian = Eigen::Matrix<double, 6, 6>::Zero ();
    Eigen::Matrix<double, 6, 1> gradient = Eigen::Matrix<double, 6, 1>::Zero ();
    for (Eigen::Index i = 0; i < points.cols (); ++i) {
      const Eigen::Vector3d rotated = R * points.col (i), h = K * (rotated + t);
      Eigen::Matrix<double, 2, 3> divide;
      divide << 1.0 / h.z (), 0.0, -h.x () / (h.z () * h.z ()), 0.0, 1.0 / h.z (), -h.y () / (h.z () * h.z ());
      Eigen::Matrix<double, 2, 6> jacobian;
      jacobian.leftCols<3> () = -divide * K * skew (rotated);
      jacobian.rightCols<3> () = divide * K;
      const Eigen::Vector2d residual = h.head<2> () / h.z () - pixels.col (i);
      hessian += jacobian.transpose () * jacobian;
      gradient -= jacobian.transpose () * residual;
    }
    hessian.diagonal () *= 1.0 + damping;
    const Eigen::Matrix<double, 6, 1> delta = hessian.ldlt ().solve (gradient);
    const double angle = delta.head<3> ().norm ();
    const Eigen::Matrix3d rotated =
        angle > 0.0 ? Eigen::AngleAxisd (angle, delta.head<3> () / angle).toRotationMatrix () * R : R;
    const Eigen::Vector3d moved = t + delta.tail<3> ();
    const double candidate = reprojectionRms (points, pixels, K, rotated, moved);
    if (candidate < rms) {
      const bool converged = rms - candidate < 1e-9 * rms;
      R = rotated, t = moved, rms = candidate, damping *= 0.3;
      if (converged)
        break;
    }
    else
      damping *= 10.0;
  }
  return rms;
}

/** The camera of intrinsics \a K posed by the weak-perspective start and Gauss-Newton; its RMS is infinite when no
 *  pose puts every point in front of it. */
CameraEstimate
posedCamera (const Eigen::Matrix3Xd& points, const Eigen::Matrix2Xd& pixels, const Eigen::Matrix3d& K,
             const std::string& source)
{
  auto [R, t] = weakPerspectivePose (points, pixels, K);
  const double rms = refinePose (points, pixels, K, R, t);
  return {PhotoCamera::perspective (K, R, t, source), rms};
}

/** \a estimate, unless its RMS is infinite: InvalidInputError naming \a source. */
CameraEstimate
requireInFront (const CameraEstimate& estimate, const std::string& source)
{
  if (!std::isfinite (estimate.rms_pixels))
    throw InvalidInputError (source + ": no camera pose puts the landmarks in front of the camera");
  return estimate;
}

/** Throws unless the points are enough and spread in 3D and the range and image size are usable. */
void
requireEstimable (const Eigen::Matrix3Xd& points, const Eigen::Matrix2Xd& pixels, const std::string& source)
{
  if (points.cols () != pixels.cols () || points.cols () < 6)
    throw InvalidInputError (source + ": a camera is estimated from at least 6 landmarks the model has, got " +
                             std::to_string (std::min (points.cols (), pixels.cols ())) + " (give the camera)");
  if (!points.allFinite () || !pixels.allFinite ())
    throw InvalidInputError (source + ": the landmarks to estimate the camera from are not finite");
  const Eigen::Matrix3Xd centred = points.colwise () - points.rowwise ().mean ();
  const Eigen::Vector3d spread =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> (centred * centred.transpose ()).eigenvalues ().cwiseMax (0.0);
  if (!(spread[0] > 1e-6 * spread[2]))
    throw InvalidInputError (source + ": the landmarks' 3D positions lie on one plane or line: they fix no camera");
}
} // namespace

FocalRange
FocalRange::forImage (int width, int height, double focal_35mm)
{
  if (focal_35mm > 0.0) {
    const double focal = focalPixelsFrom35mm (focal_35mm, width, height);
    return {focal, focal, "EXIF 35 mm focal length " + std::to_string (focal_35mm) + " mm"};
  }
  return {focalPixelsFrom35mm (kMin35mm, width, height), focalPixelsFrom35mm (kMax35mm, width, height),
          "searched over 35 mm focal lengths " + std::to_string (kMin35mm) + "-" + std::to_string (kMax35mm) +
              " mm (no EXIF focal length)"};
}

CameraEstimate
estimatePose (const Eigen::Matrix3Xd& points, const Eigen::Matrix2Xd& pixels, const Eigen::Matrix3d& K,
              const std::string& source)
{
  requireEstimable (points, pixels, source);
  return requireInFront (posedCamera (points, pixels, K, source), source);
}

CameraEstimate
estimateCamera (const Eigen::Matrix3Xd& points, const Eigen::Matrix2Xd& pixels, int width, int height,
                const FocalRange& focal, const std::string& source)
{
  if (width <= 0 || height <= 0 || !(focal.min > 0.0) || !(focal.max >= focal.min) || !std::isfinite (focal.max))
    throw InvalidInputError (source + ": the image size and the focal range must be positive");
  requireEstimable (points, pixels, source);
  const auto at = [&] (double log_focal) {
    return posedCamera (points, pixels, intrinsicsFor (std::exp (log_focal), width, height), source);
  };
  const double low = std::log (focal.min), high = std::log (focal.max);
  const int grid = focal.max > focal.min ? kFocalGrid : 1;
  if (grid == 1)
    return requireInFront (at (low), source);
  int best = 0;
  double best_rms = std::numeric_limits<double>::infinity ();
  for (int k = 0; k < grid; ++k) {
    const double rms = at (low + (high - low) * k / (grid - 1)).rms_pixels;
    if (rms < best_rms)
      best = k, best_rms = rms;
  }
  // Golden-section search between the neighbours of the best grid point.
  const double step = (high - low) / (grid - 1), golden = 0.5 * (std::sqrt (5.0) - 1.0);
  double a = std::max (low, low + (best - 1) * step), b = std::min (high, low + (best + 1) * step);
  for (int it = 0; it < kFocalRefinements; ++it) {
    const double c = b - golden * (b - a), d = a + golden * (b - a);
    if (at (c).rms_pixels < at (d).rms_pixels)
      b = d;
    else
      a = c;
  }
  return requireInFront (at (0.5 * (a + b)), source);
}
} // namespace morphreg
