// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file initial_alignment.h
 *  \brief Starting similarities for MorphableICP: from landmark pairs (Umeyama), or a coarse guess from centroids,
 *  principal axes and extents for scans whose orientation is roughly known.
 */
#include <pcl/types.h>

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace morphreg
{
/** \brief The least-squares similarity [sR | t] (Umeyama) mapping \a source onto \a target (3 x K, K >= 3 pairs).
 *  Throws InvalidInputError for fewer than 3 pairs, mismatched sizes, non-finite values or collinear points.
 *  \param[in] source the source landmarks (3 x K, e.g. the model's)
 *  \param[in] target the corresponding target landmarks (3 x K, e.g. the scan's, mm)
 *  \return the 4 x 4 similarity mapping source onto target
 */
Eigen::Matrix4d
similarityFromLandmarks (const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target);

/** \brief A coarse similarity mapping the point set \a source onto \a target (e.g. a model mean onto a scan).
 *  Both sets are trimmed to the 90 % of points closest to their coordinate-wise median (so outliers matter
 *  little); then translation from the centroids, scale from the RMS spreads and rotation from the principal
 *  axes matched in order of extent, each signed to agree with the source's. The orientation is assumed roughly
 *  known: if the axes imply a rotation above \a max_rotation_deg (ambiguous extents, e.g. a round object),
 *  the rotation is left at identity. Throws InvalidInputError for fewer than 4 points or non-finite values.
 *  \param[in] source the points mapped (3 x N)
 *  \param[in] target the points mapped onto (3 x M)
 *  \param[in] max_rotation_deg the largest rotation (degrees) the principal axes may imply
 *  \return the 4 x 4 similarity mapping source onto target
 */
Eigen::Matrix4d
coarseSimilarity (const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target, double max_rotation_deg = 45.0);

/** \brief Settings of robustCoarseSimilarity. */
struct CoarseAlignmentSettings
{
  double hypothesis_angle_deg = 25.0; ///< tilt of the extra hypotheses about each axis, both directions
  int sample_points = 2000;           ///< source points (evenly strided) used by the refinement and the score
  int refine_iterations = 20;         ///< similarity-only ICP iterations per hypothesis that runs to the end
  int screen_iterations = 5;          ///< iterations every hypothesis runs before the best-scoring ones go on
  int survivors = 4;                  ///< hypotheses that go on after the screening
  double inlier_fraction = 0.7;       ///< share of the closest pairs kept in each refinement step and the score
  double tie_tolerance = 0.05;        ///< relative score margin within which the hypothesis rotating less wins
};

/** \brief A coarse similarity mapping \a source onto \a target that tolerates holes, outliers and extra parts.
 *  Starts from several pose hypotheses sharing the trimmed centroids and spreads of coarseSimilarity: identity
 *  rotation, the principal-axis rotation in its four proper sign variants, and tilts by
 *  settings.hypothesis_angle_deg about each axis. Each is refined by settings.screen_iterations trimmed
 *  point-to-plane similarity-only ICP steps (source samples -> closest target points) and scored by the trimmed
 *  mean of the source -> target and target -> source closest-point distances; the settings.survivors best go on to
 *  settings.refine_iterations steps and are scored again. Among them the lowest score wins, and among scores within
 *  settings.tie_tolerance of it the smallest rotation (scans in roughly known orientation). Returns the refined
 *  winner. Throws InvalidInputError for fewer than 4 points, non-finite values, no spread or bad settings.
 *  \param[in] source the points mapped (3 x N, e.g. the model's mean)
 *  \param[in] target the points mapped onto (3 x M, e.g. the scan)
 *  \param[in] settings the hypotheses, refinement and scoring
 *  \return the refined winning similarity (4 x 4), source onto target
 */
Eigen::Matrix4d
robustCoarseSimilarity (const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target,
                        const CoarseAlignmentSettings& settings = CoarseAlignmentSettings ());

/** \brief The \a k nearest target points of target point \a i (itself included): their indices and squared distances,
 *  as pcl::search::Search::nearestKSearch gives them. Called from several threads at once.
 */
using TargetNeighbourSearch =
    std::function<void (Eigen::Index i, int k, pcl::Indices& indices, std::vector<float>& squared_distances)>;

/** \brief robustCoarseSimilarity with the target's neighbourhoods from a search the caller already has (e.g. a
 *  registration's target k-d tree), so the target's tree is not built a second time.
 *  \param[in] source the points mapped (3 x N)
 *  \param[in] target the points mapped onto (3 x M)
 *  \param[in] target_neighbours the k-nearest-neighbour search over \a target
 *  \param[in] settings the hypotheses, refinement and scoring
 *  \return the refined winning similarity (4 x 4), source onto target
 */
Eigen::Matrix4d
robustCoarseSimilarity (const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target,
                        const TargetNeighbourSearch& target_neighbours,
                        const CoarseAlignmentSettings& settings = CoarseAlignmentSettings ());

} // namespace morphreg
