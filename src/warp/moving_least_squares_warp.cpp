// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/warp/impl/landmark_pairs.h>
#include <morphreg/warp/moving_least_squares_warp.h>

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace morphreg
{
namespace
{
/** A point closer to a landmark than this fraction of the landmarks' extent is that landmark (its weight would
 *  overflow): it goes to the landmark's target, as the limit of the warp does. */
constexpr double kCoincidence = 1e-9;
/** Points warped together: the landmark loop runs over a block's points in vector registers. */
constexpr Eigen::Index kBlock = 256;
} // namespace

void
MovingLeastSquaresWarp::setLandmarks (const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target)
{
  const detail::LandmarkPairs pairs =
      detail::distinctLandmarkPairs (source, target, "MovingLeastSquaresWarp", "moving least squares warp");
  source_ = pairs.source.transpose ();
  target_ = pairs.target.transpose ();
  merged_ = pairs.merged;
  coincidence_ = kCoincidence * detail::boundingBoxDiagonal (source_);
}

void
MovingLeastSquaresWarp::setFalloff (double alpha)
{
  if (!(alpha > 0.0) || !std::isfinite (alpha))
    throw InvalidInputError ("MovingLeastSquaresWarp: the falloff exponent must be finite and > 0, got " +
                             std::to_string (alpha));
  alpha_ = alpha;
}

Eigen::ArrayXd
MovingLeastSquaresWarp::weights (const Eigen::ArrayXd& squared_distances) const
{
  if (alpha_ == 1.0)
    return squared_distances.inverse ();
  return squared_distances.pow (-alpha_);
}

void
MovingLeastSquaresWarp::warpBlock (const Eigen::Ref<const Eigen::Matrix3Xd>& points,
                                   Eigen::Ref<Eigen::Matrix3Xd> warped) const
{
  // Weighted moments about each point, over the landmarks. With u_i = p_i - x and the displacements d_i = q_i - p_i
  // they stay bounded near a landmark (w |u|^2 = 1), where moments about the origin would cancel. One row per point
  // and one column per moment, so every update below is a contiguous vector operation. Columns: sum w; sum w u (3);
  // sum w d (3); sum w u u^T (9); sum w d u^T (9, column-major).
  Eigen::ArrayXXd moments = Eigen::ArrayXXd::Zero (points.cols (), 25);
  const Eigen::ArrayXXd x = points.transpose ();
  std::vector<Eigen::Index> at_landmark (static_cast<std::size_t> (points.cols ()), -1);
  Eigen::ArrayXXd u (points.cols (), 3);
  for (Eigen::Index i = 0; i < source_.cols (); ++i) {
    for (int r = 0; r < 3; ++r)
      u.col (r) = source_ (r, i) - x.col (r);
    const Eigen::ArrayXd squared = u.square ().rowwise ().sum ();
    const Eigen::ArrayXd w = weights (squared.max (coincidence_ * coincidence_));
    const Eigen::Array3d d = target_.col (i) - source_.col (i);
    moments.col (0) += w;
    for (int r = 0; r < 3; ++r) {
      const Eigen::ArrayXd wu = w * u.col (r);
      moments.col (1 + r) += wu;
      moments.col (4 + r) += d (r) * w;
      for (int c = 0; c < 3; ++c) {
        moments.col (7 + 3 * r + c) += wu * u.col (c);
        moments.col (16 + 3 * r + c) += d (c) * wu;
      }
    }
    for (Eigen::Index j = 0; j < points.cols (); ++j)
      if (squared (j) <= coincidence_ * coincidence_)
        at_landmark[static_cast<std::size_t> (j)] = i;
  }
  for (Eigen::Index j = 0; j < points.cols (); ++j) {
    if (at_landmark[static_cast<std::size_t> (j)] >= 0) {
      warped.col (j) = target_.col (at_landmark[static_cast<std::size_t> (j)]);
      continue;
    }
    const Eigen::Matrix<double, 25, 1> m = moments.row (j).transpose ();
    const double total = m (0);
    const Eigen::Vector3d u_mean = m.segment<3> (1) / total, d_mean = m.segment<3> (4) / total;
    const Eigen::Matrix3d uu = Eigen::Map<const Eigen::Matrix3d> (m.data () + 7);
    const Eigen::Matrix3d du = Eigen::Map<const Eigen::Matrix3d> (m.data () + 16);
    // The weighted best affine map p_i -> q_i, at x: f(x) = x + d_mean + B^T A^-1 (x - p_mean), with x - p_mean =
    // -u_mean and the weighted covariances A = sum w (p_i - p_mean)(p_i - p_mean)^T = uu - total u_mean u_mean^T and
    // B = sum w (p_i - p_mean)(d_i - d_mean)^T = du^T - total u_mean d_mean^T. A is positive definite unless the
    // landmarks are coplanar.
    const Eigen::Matrix3d a = uu - total * u_mean * u_mean.transpose ();
    const Eigen::Matrix3d b = du.transpose () - total * u_mean * d_mean.transpose ();
    warped.col (j) = points.col (j) + d_mean - b.transpose () * a.ldlt ().solve (u_mean);
  }
}

Eigen::Matrix3Xd
MovingLeastSquaresWarp::transformPoints (const Eigen::Matrix3Xd& points) const
{
  if (source_.cols () == 0)
    throw InvalidInputError ("MovingLeastSquaresWarp: no landmarks set (call setLandmarks first)");
  if (!points.allFinite ())
    throw InvalidInputError ("MovingLeastSquaresWarp: a point to warp is not finite (NaN or Inf)");
  Eigen::Matrix3Xd warped (3, points.cols ());
  const Eigen::Index blocks = (points.cols () + kBlock - 1) / kBlock;
#pragma omp parallel for schedule(static)
  for (Eigen::Index k = 0; k < blocks; ++k) {
    const Eigen::Index start = k * kBlock, size = std::min (kBlock, points.cols () - start);
    warpBlock (points.middleCols (start, size), warped.middleCols (start, size));
  }
  if (!warped.allFinite ())
    throw NumericalError ("MovingLeastSquaresWarp: a warped point is not finite (landmarks too close to flat?)");
  return warped;
}

TriangleMesh
MovingLeastSquaresWarp::warp (const TriangleMesh& mesh) const
{
  validateMesh (mesh, "mesh to warp");
  TriangleMesh warped = mesh;
  warped.vertices = transformPoints (mesh.vertices);
  return warped;
}

void
MovingLeastSquaresWarp::warp (const pcl::PolygonMesh& input, pcl::PolygonMesh& output) const
{
  output = toPolygonMesh (warp (fromPolygonMesh (input, "mesh to warp")));
}

} // namespace morphreg
