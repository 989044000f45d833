// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file scan_checks.h
 *  \brief Checks that a scan can be registered at all, before any fitting: enough finite points spread in 3D.
 */
#include <morphreg/common/landmarks.h>

#include <Eigen/Core>

#include <string>

namespace morphreg
{
/** \brief Throws InvalidInputError naming \a name (e.g. the file) when \a points (3 x N) cannot be registered to a
 *  head model: fewer than 100 points, a non-finite coordinate, a stray point (farther from the points' median than
 *  10^4 times their median distance from it), all points identical, collinear, or flat (the
 *  smallest principal spread below 1e-3 of the largest: a head scan is three-dimensional). Each case has its own
 *  message with the numbers.
 *  \param[in] points the scan points (3 x N)
 *  \param[in] name what the points are (e.g. the file), for the message
 */
void
requireRegistrableScan (const Eigen::Matrix3Xd& points, const std::string& name);

/** \brief Throws InvalidInputError naming \a name, the point and the length when a scan normal is neither missing
 *  (zero or NaN: estimated from the neighbours) nor of a length from 0.5 to 2: normals are unit vectors, and one of
 *  length 10^30 is a corrupt file, not a direction to fit along.
 *  \param[in] normals the scan's normals (3 x N)
 *  \param[in] name the scan file, for the message
 */
void
requireUnitNormals (const Eigen::Matrix3Xd& normals, const std::string& name);

/** \brief Throws InvalidInputError naming \a name when a landmark lies farther from the scan's bounding box than the
 *  box's diagonal: landmarks marked on a scan lie on it, so such a file is in another frame or in another unit than
 *  it declares (e.g. millimetre values in a file whose "units" says metres); or when three or more landmarks spread
 *  less than a tenth of what the scan does (landmarks in a smaller unit that still fall inside the scan's box).
 *  \param[in] landmarks the landmarks, in the scan's frame and unit
 *  \param[in] points the scan points (3 x N, finite)
 *  \param[in] name the landmark file, for the message
 */
void
requireLandmarksOnScan (const LandmarkPositions& landmarks, const Eigen::Matrix3Xd& points, const std::string& name);

} // namespace morphreg
