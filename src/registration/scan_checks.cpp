// SPDX-License-Identifier: BSD-3-Clause
#include "../common/number_text.h"

#include <morphreg/common/error.h>
#include <morphreg/registration/scan_checks.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <string>

namespace morphreg
{
namespace
{
using detail::numberText;

constexpr Eigen::Index kMinimumPoints = 100;
/** Relative spreads below which the points count as one point, a line or a plane (see scan_checks.h). */
constexpr double kIdenticalSpread = 1e-9;
constexpr double kCollinearSpread = 1e-6;
constexpr double kFlatSpread = 1e-3;

std::string
pointText (const Eigen::Vector3d& p)
{
  return '(' + numberText (p.x (), 6) + ", " + numberText (p.y (), 6) + ", " + numberText (p.z (), 6) + ')';
}

/** Throws when a column of \a points has a non-finite coordinate, naming the first. */
void
requireFinitePoints (const Eigen::Matrix3Xd& points, const std::string& name)
{
  for (Eigen::Index i = 0; i < points.cols (); ++i)
    if (!points.col (i).allFinite ())
      throw InvalidInputError (name + ": point " + std::to_string (i) + " is not finite " + pointText (points.col (i)));
}

/** Throws when \a points are one point, on a line or in a plane: their principal spreads (standard deviations along
 *  the covariance's eigenvectors) against the largest. */
void
requireThreeDimensionalSpread (const Eigen::Matrix3Xd& points, const std::string& name)
{
  const std::string count = std::to_string (points.cols ());
  const Eigen::Vector3d centroid = points.rowwise ().mean ();
  const Eigen::Matrix3Xd centred = points.colwise () - centroid;
  const Eigen::Matrix3d covariance = centred * centred.transpose () / static_cast<double> (points.cols ());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (covariance);
  const Eigen::Vector3d spread = solver.eigenvalues ().cwiseMax (0.0).cwiseSqrt (); // ascending
  const double magnitude = std::max (centroid.cwiseAbs ().maxCoeff (), 1.0); // rounding grows with the coordinates
  if (spread[2] <= kIdenticalSpread * magnitude)
    throw InvalidInputError (name + ": all " + count + " points are identical " + pointText (centroid));
  if (spread[1] <= kCollinearSpread * spread[2])
    throw InvalidInputError (name + ": the " + count + " points are collinear (they spread " + numberText (spread[2]) +
                             " along a line and " + numberText (spread[1]) + " across it)");
  if (spread[0] < kFlatSpread * spread[2])
    throw InvalidInputError (name + ": the " + count + " points lie in a plane (spread " + numberText (spread[0]) +
                             " across it against " + numberText (spread[2]) +
                             " along it); a head scan is three-dimensional");
}
} // namespace

void
requireRegistrableScan (const Eigen::Matrix3Xd& points, const std::string& name)
{
  if (points.cols () < kMinimumPoints)
    throw InvalidInputError (name + ": " + std::to_string (points.cols ()) + " points, at least " +
                             std::to_string (kMinimumPoints) + " are needed to register a scan");
  requireFinitePoints (points, name);
  requireThreeDimensionalSpread (points, name);
}

void
requireLandmarksOnScan (const LandmarkPositions& landmarks, const Eigen::Matrix3Xd& points, const std::string& name)
{
  const Eigen::Vector3d low = points.rowwise ().minCoeff (), high = points.rowwise ().maxCoeff ();
  const double diagonal = (high - low).norm ();
  for (const auto& [id, position] : landmarks) {
    const double outside = (position - position.cwiseMax (low).cwiseMin (high)).norm ();
    if (!(outside <= diagonal))
      throw InvalidInputError (name + ": landmark " + id + " " + pointText (position) + " lies " +
                               numberText (outside) + " mm outside the scan, whose bounding box is " +
                               numberText (diagonal) +
                               " mm across; are the file's units (and \"units\" field) and frame the scan's?");
  }
}

} // namespace morphreg
