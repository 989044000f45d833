#include <morphreg/common/error.h>
#include <morphreg/registration/initial_alignment.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace morphreg
{
namespace
{
/** Centroid and covariance of the 90 % of \a points nearest to their coordinate-wise median. */
struct RobustMoments
{
  Eigen::Vector3d centroid;
  Eigen::Matrix3d covariance;
};

double
median (std::vector<double> values)
{
  const auto mid = values.begin () + static_cast<long> (values.size () / 2);
  std::nth_element (values.begin (), mid, values.end ());
  return *mid;
}

RobustMoments
trimmedMoments (const Eigen::Matrix3Xd& points)
{
  Eigen::Vector3d centre;
  for (int d = 0; d < 3; ++d) {
    const Eigen::RowVectorXd row = points.row (d);
    centre[d] = median (std::vector<double> (row.data (), row.data () + row.size ()));
  }
  std::vector<double> distances (points.cols ());
  for (Eigen::Index i = 0; i < points.cols (); ++i)
    distances[i] = (points.col (i) - centre).squaredNorm ();
  std::vector<double> sorted = distances;
  const auto keep = std::max<size_t> (4, static_cast<size_t> (0.9 * static_cast<double> (sorted.size ())));
  std::nth_element (sorted.begin (), sorted.begin () + static_cast<long> (keep - 1), sorted.end ());
  const double limit = sorted[keep - 1];

  RobustMoments moments{Eigen::Vector3d::Zero (), Eigen::Matrix3d::Zero ()};
  double count = 0.0;
  for (Eigen::Index i = 0; i < points.cols (); ++i)
    if (distances[i] <= limit) {
      moments.centroid += points.col (i);
      count += 1.0;
    }
  moments.centroid /= count;
  for (Eigen::Index i = 0; i < points.cols (); ++i)
    if (distances[i] <= limit) {
      const Eigen::Vector3d d = points.col (i) - moments.centroid;
      moments.covariance += d * d.transpose ();
    }
  moments.covariance /= count;
  return moments;
}

/** Eigenvectors of \a covariance as columns, by decreasing eigenvalue. */
Eigen::Matrix3d
principalAxes (const Eigen::Matrix3d& covariance)
{
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (covariance);
  return solver.eigenvectors ().rowwise ().reverse ();
}

void
requirePoints (const Eigen::Matrix3Xd& points, Eigen::Index minimum, const std::string& what)
{
  if (points.cols () < minimum)
    throw InvalidInputError (what + ": " + std::to_string (points.cols ()) + " points, at least " +
                             std::to_string (minimum) + " needed");
  if (!points.allFinite ())
    throw InvalidInputError (what + ": points are not finite");
}
} // namespace

Eigen::Matrix4d
similarityFromLandmarks (const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target)
{
  requirePoints (source, 3, "similarityFromLandmarks (source)");
  requirePoints (target, 3, "similarityFromLandmarks (target)");
  if (source.cols () != target.cols ())
    throw InvalidInputError ("similarityFromLandmarks: " + std::to_string (source.cols ()) + " source and " +
                             std::to_string (target.cols ()) + " target landmarks");
  for (const Eigen::Matrix3Xd* points : {&source, &target}) {
    const Eigen::Matrix3Xd centred = points->colwise () - points->rowwise ().mean ();
    const Eigen::JacobiSVD<Eigen::Matrix3Xd> svd (centred);
    if (svd.singularValues ()[1] <= 1e-9 * std::max (1.0, svd.singularValues ()[0]))
      throw InvalidInputError ("similarityFromLandmarks: the landmarks are collinear or coincide");
  }
  return Eigen::umeyama (source, target, true);
}

Eigen::Matrix4d
coarseSimilarity (const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target, double max_rotation_deg)
{
  requirePoints (source, 4, "coarseSimilarity (source)");
  requirePoints (target, 4, "coarseSimilarity (target)");
  const RobustMoments from = trimmedMoments (source);
  const RobustMoments to = trimmedMoments (target);
  const double spread_from = from.covariance.trace ();
  if (spread_from <= 0.0 || to.covariance.trace () <= 0.0)
    throw InvalidInputError ("coarseSimilarity: the points have no spread");
  const double scale = std::sqrt (to.covariance.trace () / spread_from);

  const Eigen::Matrix3d axes_from = principalAxes (from.covariance);
  Eigen::Matrix3d axes_to = principalAxes (to.covariance);
  for (int k = 0; k < 3; ++k)
    if (axes_to.col (k).dot (axes_from.col (k)) < 0.0)
      axes_to.col (k) *= -1.0;
  Eigen::Matrix3d rotation = axes_to * axes_from.transpose ();
  if (rotation.determinant () < 0.0) {
    axes_to.col (2) *= -1.0;
    rotation = axes_to * axes_from.transpose ();
  }
  const double angle = Eigen::AngleAxisd (rotation).angle ();
  if (angle > max_rotation_deg * M_PI / 180.0)
    rotation.setIdentity ();

  Eigen::Matrix4d similarity = Eigen::Matrix4d::Identity ();
  similarity.topLeftCorner<3, 3> () = scale * rotation;
  similarity.topRightCorner<3, 1> () = to.centroid - scale * rotation * from.centroid;
  return similarity;
}

} // namespace morphreg
