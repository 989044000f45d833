#pragma once
/** \file initial_alignment.h
 *  \brief Starting similarities for MorphableICP: from landmark pairs (Umeyama), or a coarse guess from centroids,
 *  principal axes and extents for scans whose orientation is roughly known.
 */
#include <Eigen/Core>

namespace morphreg
{
/** \brief The least-squares similarity [sR | t] (Umeyama) mapping \a source onto \a target (3 x K, K >= 3 pairs).
 *  Throws InvalidInputError for fewer than 3 pairs, mismatched sizes, non-finite values or collinear points.
 */
Eigen::Matrix4d
similarityFromLandmarks (const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target);

/** \brief A coarse similarity mapping the point set \a source onto \a target (e.g. a model mean onto a scan).
 *  Both sets are trimmed to the 90 % of points closest to their coordinate-wise median (so outliers matter
 *  little); then translation from the centroids, scale from the RMS spreads and rotation from the principal
 *  axes matched in order of extent, each signed to agree with the source's. The orientation is assumed roughly
 *  known: if the axes imply a rotation above \a max_rotation_deg (ambiguous extents, e.g. a round object),
 *  the rotation is left at identity. Throws InvalidInputError for fewer than 4 points or non-finite values.
 */
Eigen::Matrix4d
coarseSimilarity (const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target, double max_rotation_deg = 45.0);

} // namespace morphreg
