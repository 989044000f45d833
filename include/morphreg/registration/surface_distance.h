// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file surface_distance.h
 *  \brief How close a fitted model surface lies to a target surface without known correspondence, the accuracy
 *  measure for real targets: area-uniform samples of the target, each to the closest point on the fitted surface
 *  (point-to-triangle), leaving out samples that only reach the fitted surface at its open boundary (target parts
 *  the model lacks).
 */
#include <morphreg/mesh/triangle_mesh.h>

#include <cstdint>
#include <vector>

namespace morphreg
{
/** \brief How the target is sampled and which samples count. */
struct SurfaceDistanceSettings
{
  double area_per_sample = 4.0; ///< mm^2 of target surface per sample
  std::uint64_t seed = 1;       ///< the sampling is deterministic for a seed
  bool drop_boundary = true;    ///< leave out samples whose closest fitted point lies on the fitted boundary
};

/** \brief Distances (mm) of the kept target samples to the fitted surface, and their statistics. */
struct SurfaceDistance
{
  std::vector<double> distances;     ///< per kept sample
  std::vector<int> fitted_triangles; ///< per kept sample: the fitted triangle its closest point lies on
  int samples = 0;                   ///< samples drawn (before dropping)
  int dropped_on_boundary = 0;       ///< samples whose closest fitted point lies on the fitted boundary
  double mean = 0.0;                 ///< mean distance (mm) of the kept samples
  double median = 0.0;               ///< median distance (mm)
  double percentile95 = 0.0;         ///< 95th percentile of the distances (mm)
  double rms = 0.0;                  ///< root mean square distance (mm)
  double max = 0.0;                  ///< largest distance (mm)
};

/** \brief Samples \a target (without the triangles flagged in \a excluded_target, e.g. a scanner's closing cap)
 *  and measures each sample's distance to the closest point of \a fitted. Throws InvalidInputError for invalid
 *  meshes or settings, a wrongly sized \a excluded_target, or when no sample is left.
 *  \param[in] target the surface sampled (mm)
 *  \param[in] fitted the fitted model surface the samples are measured to (mm)
 *  \param[in] excluded_target one flag per target triangle, true to leave it unsampled; or empty
 *  \param[in] settings the sampling density, seed and boundary rule
 *  \return the kept samples' distances (mm), the fitted triangle each lands on, and their statistics
 */
SurfaceDistance
surfaceDistance (const TriangleMesh& target, const TriangleMesh& fitted, const std::vector<bool>& excluded_target = {},
                 const SurfaceDistanceSettings& settings = {});

/** \brief Each of \a points (3 x N, mm) to the closest point of \a fitted, leaving out (with \a drop_boundary) the
 *  points that reach it only at its open boundary: the distances and their statistics (zero when none is kept).
 *  Throws InvalidInputError for an invalid mesh.
 *  \param[in] points the points measured, e.g. a scan's
 *  \param[in] fitted the fitted model surface (mm)
 *  \param[in] drop_boundary leave out points whose closest fitted point lies on the fitted boundary
 *  \return the kept points' distances (mm), the fitted triangle each lands on, and their statistics
 */
SurfaceDistance
pointDistances (const Eigen::Matrix3Xd& points, const TriangleMesh& fitted, bool drop_boundary = true);

/** \brief The statistics of the kept samples whose closest point lies on a fitted triangle flagged in
 *  \a triangles (one flag per fitted triangle), e.g. the face of a head model; \a distance as surfaceDistance
 *  returned it. Throws InvalidInputError for a wrongly sized \a triangles or when no sample lands on them.
 *  \param[in] distance a result of surfaceDistance on the same fitted mesh
 *  \param[in] triangles one flag per fitted triangle, true for the part measured
 *  \return the samples landing on the flagged triangles and their statistics (mm); samples and
 *  dropped_on_boundary as in \a distance
 */
SurfaceDistance
surfaceDistanceOver (const SurfaceDistance& distance, const std::vector<bool>& triangles);

} // namespace morphreg
