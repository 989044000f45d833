#include <morphreg/common/error.h>
#include <morphreg/registration/scan_checks.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <sstream>

namespace morphreg
{
namespace
{
constexpr Eigen::Index kMinimumPoints = 100;

std::string
pointText (const Eigen::Vector3d& p)
{
  std::ostringstream text;
  text << '(' << p.x () << ", " << p.y () << ", " << p.z () << ')';
  return text.str ();
}
} // namespace

void
requireRegistrableScan (const Eigen::Matrix3Xd& points, const std::string& name)
{
  const Eigen::Index n = points.cols ();
  if (n < kMinimumPoints)
    throw InvalidInputError (name + ": " + std::to_string (n) + " points, at least " +
                             std::to_string (kMinimumPoints) + " are needed to register a scan");
  for (Eigen::Index i = 0; i < n; ++i)
    if (!points.col (i).allFinite ())
      throw InvalidInputError (name + ": point " + std::to_string (i) + " is not finite " +
                               pointText (points.col (i)));
  const Eigen::Vector3d centroid = points.rowwise ().mean ();
  const Eigen::Matrix3Xd centred = points.colwise () - centroid;
  const Eigen::Matrix3d covariance = centred * centred.transpose () / static_cast<double> (n);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (covariance);
  const Eigen::Vector3d spread = solver.eigenvalues ().cwiseMax (0.0).cwiseSqrt (); // ascending
  const double scale = std::max (centroid.cwiseAbs ().maxCoeff (), 1.0);
  if (spread[2] <= 1e-9 * scale)
    throw InvalidInputError (name + ": all " + std::to_string (n) + " points are identical " + pointText (centroid));
  if (spread[1] <= 1e-6 * spread[2])
    throw InvalidInputError (name + ": the " + std::to_string (n) + " points are collinear (they spread " +
                             std::to_string (spread[2]) + " along a line and " + std::to_string (spread[1]) +
                             " across it)");
  if (spread[0] < 1e-3 * spread[2])
    throw InvalidInputError (name + ": the " + std::to_string (n) + " points lie in a plane (spread " +
                             std::to_string (spread[0]) + " across it against " + std::to_string (spread[2]) +
                             " along it); a head scan is three-dimensional");
}

} // namespace morphreg
