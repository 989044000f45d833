// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file landmark_pairs.h
 *  \brief The checks and merging every landmark warp (thin plate spline, moving least squares) applies to its
 *  landmark pairs. Internal; the warps call it.
 */
#include <Eigen/Core>

#include <string>

namespace morphreg
{
namespace detail
{
/** \brief Landmark pairs ready for a warp: one row per distinct source landmark. */
struct LandmarkPairs
{
  Eigen::MatrixXd source;        ///< n x d distinct source landmarks
  Eigen::MatrixXd target;        ///< n x d their targets
  Eigen::Index merged = 0;       ///< pairs dropped as duplicates of an earlier pair
  double affine_condition = 0.0; ///< widest / thinnest spread of the sources, the conditioning of an affine fit
};

/** \brief The diagonal of the bounding box of the columns of \a points, the scale landmark tolerances are relative to.
 *  \param[in] points d x n points
 *  \return the diagonal's length
 */
double
boundingBoxDiagonal (const Eigen::MatrixXd& points);

/** \brief The pairs of columns of \a source and \a target (d x n, d = 2 or 3), coincident sources with coincident
 *  targets merged. Throws InvalidInputError, prefixed with \a caller, for mismatched counts or dimensions,
 *  non-finite landmarks, coincident sources with different targets, fewer than d + 1 distinct landmarks or
 *  landmarks that do not span d dimensions (coplanar or collinear); \a method names the warp in the messages
 *  (e.g. "thin plate spline").
 *  \param[in] source source landmarks as columns
 *  \param[in] target target landmarks as columns
 *  \param[in] caller prefix of error messages, e.g. "ThinPlateSpline::fit"
 *  \param[in] method the warp's name for the messages
 *  \return the distinct pairs
 */
LandmarkPairs
distinctLandmarkPairs (const Eigen::MatrixXd& source, const Eigen::MatrixXd& target, const std::string& caller,
                       const std::string& method);

} // namespace detail
} // namespace morphreg
