// SPDX-License-Identifier: BSD-3-Clause
#include "../common/number_text.h"

#include <morphreg/common/error.h>
#include <morphreg/registration/scan_checks.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

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

/** Throws when one point of \a points lies implausibly far from the others (10^4 times their median distance from
 *  their coordinate-wise median): a stray point, which would otherwise pass for a line, a plane or a wrong unit. */
void
requireNoStrayPoint (const Eigen::Matrix3Xd& points, const std::string& name)
{
  Eigen::Vector3d centre;
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double> values (static_cast<std::size_t> (points.cols ()));
    for (Eigen::Index i = 0; i < points.cols (); ++i)
      values[static_cast<std::size_t> (i)] = points (axis, i);
    std::nth_element (values.begin (), values.begin () + values.size () / 2, values.end ());
    centre[axis] = values[values.size () / 2];
  }
  Eigen::VectorXd distances = (points.colwise () - centre).colwise ().norm ().transpose ();
  Eigen::Index farthest = 0;
  const double largest = distances.maxCoeff (&farthest);
  std::nth_element (distances.data (), distances.data () + distances.size () / 2,
                    distances.data () + distances.size ());
  const double typical = distances[distances.size () / 2];
  if (typical > 0.0 && largest > 1e4 * typical)
    throw InvalidInputError (name + ": point " + std::to_string (farthest) + " " + pointText (points.col (farthest)) +
                             " lies " + numberText (largest) + " from the scan's centre, whose points lie " +
                             numberText (typical) + " from it (median): a stray point (a corrupt file?)");
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
/** Throws when three or more landmarks spread less than a tenth of what the scan does (RMS distances from their
 *  centroids): landmarks of a face on a head scan spread about half as much; far less is another unit. */
void
requireLandmarkScale (const LandmarkPositions& landmarks, const Eigen::Matrix3Xd& points, const std::string& name)
{
  if (landmarks.size () < 3)
    return;
  Eigen::Matrix3Xd marked (3, static_cast<Eigen::Index> (landmarks.size ()));
  Eigen::Index k = 0;
  for (const auto& entry : landmarks)
    marked.col (k++) = entry.second;
  const auto spread = [] (const Eigen::Matrix3Xd& p) {
    return std::sqrt ((p.colwise () - p.rowwise ().mean ()).colwise ().squaredNorm ().mean ());
  };
  const double landmark_spread = spread (marked), scan_spread = spread (points);
  if (landmark_spread < 0.1 * scan_spread)
    throw InvalidInputError (name + ": the " + std::to_string (landmarks.size ()) + " landmarks spread " +
                             numberText (landmark_spread) + " mm around their centre, the scan " +
                             numberText (scan_spread) +
                             " mm (at least a tenth of that is expected): are the "
                             "landmarks in the scan's unit?");
}
} // namespace

void
requireRegistrableScan (const Eigen::Matrix3Xd& points, const std::string& name)
{
  if (points.cols () < kMinimumPoints)
    throw InvalidInputError (name + ": " + std::to_string (points.cols ()) + " points, at least " +
                             std::to_string (kMinimumPoints) + " are needed to register a scan");
  requireFinitePoints (points, name);
  requireNoStrayPoint (points, name);
  requireThreeDimensionalSpread (points, name);
}

void
requireUnitNormals (const Eigen::Matrix3Xd& normals, const std::string& name)
{
  for (Eigen::Index i = 0; i < normals.cols (); ++i) {
    const double length = normals.col (i).norm ();
    if (std::isnan (length) || length == 0.0 || (length >= 0.5 && length <= 2.0))
      continue;
    throw InvalidInputError (name + ": the normal of point " + std::to_string (i) + " " + pointText (normals.col (i)) +
                             " has the length " + numberText (length) +
                             "; normals must be unit vectors (0.5 to 2, or 0 for none)");
  }
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
  requireLandmarkScale (landmarks, points, name);
}

} // namespace morphreg
