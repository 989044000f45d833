#include <morphreg/common/error.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/warp/impl/landmark_pairs.h>
#include <morphreg/warp/moving_least_squares_warp.h>

#include <Eigen/Cholesky>

#include <cmath>
#include <string>

namespace morphreg
{
namespace
{
/** A point closer to a landmark than this fraction of the landmarks' extent is that landmark (its weight would
 *  overflow): it goes to the landmark's target, as the limit of the warp does. */
constexpr double kCoincidence = 1e-9;
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

Eigen::Vector3d
MovingLeastSquaresWarp::transformPoint (const Eigen::Vector3d& point) const
{
  const Eigen::VectorXd squared = (source_.colwise () - point).colwise ().squaredNorm ().transpose ();
  Eigen::Index nearest = 0;
  if (squared.minCoeff (&nearest) <= coincidence_ * coincidence_)
    return target_.col (nearest);
  const Eigen::VectorXd weights = squared.array ().pow (-alpha_);
  const Eigen::Vector3d p = source_ * weights / weights.sum (), q = target_ * weights / weights.sum ();
  const Eigen::Matrix3Xd from = source_.colwise () - p, to = target_.colwise () - q;
  // The affine map M minimising sum w_i |M^T (p_i - p) - (q_i - q)|^2 is M = A^-1 B with A = sum w (p_i - p)(p_i -
  // p)^T and B = sum w (p_i - p)(q_i - q)^T; A is positive definite for landmarks that are not coplanar.
  const Eigen::Matrix3d a = from * weights.asDiagonal () * from.transpose ();
  const Eigen::Matrix3d b = from * weights.asDiagonal () * to.transpose ();
  return q + b.transpose () * a.ldlt ().solve (point - p);
}

Eigen::Matrix3Xd
MovingLeastSquaresWarp::transformPoints (const Eigen::Matrix3Xd& points) const
{
  if (source_.cols () == 0)
    throw InvalidInputError ("MovingLeastSquaresWarp: no landmarks set (call setLandmarks first)");
  if (!points.allFinite ())
    throw InvalidInputError ("MovingLeastSquaresWarp: a point to warp is not finite (NaN or Inf)");
  Eigen::Matrix3Xd warped (3, points.cols ());
#pragma omp parallel for schedule(static)
  for (Eigen::Index i = 0; i < points.cols (); ++i)
    warped.col (i) = transformPoint (points.col (i));
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
