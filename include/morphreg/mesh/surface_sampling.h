// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file surface_sampling.h
 *  \brief Random points spread uniformly by area over a triangle mesh (evaluation samples, simulated scans).
 */
#include <morphreg/mesh/triangle_mesh.h>

#include <cstdint>
#include <vector>

namespace morphreg
{
/** \brief Surface samples and the triangle each lies on. */
struct SurfaceSamples
{
  Eigen::Matrix3Xd points;    ///< 3 x S sample positions (mm)
  std::vector<int> triangles; ///< per sample: its triangle
};

/** \brief About one sample per \a area_per_sample mm^2 (round(area / area_per_sample), at least one), each on a
 *  triangle drawn with probability proportional to its area and uniform inside it; deterministic for a \a seed.
 *  Triangles flagged in \a excluded (empty = none; else one flag per triangle) get no samples and do not count
 *  towards the area. Throws InvalidInputError for an invalid mesh, a non-positive \a area_per_sample, a wrongly
 *  sized \a excluded or no area left to sample.
 *  \param[in] mesh the surface
 *  \param[in] area_per_sample mm^2 of surface per sample
 *  \param[in] seed the random seed
 *  \param[in] excluded per triangle, true to leave it out; empty to sample every triangle
 *  \return the samples and their triangles
 */

SurfaceSamples
sampleSurfaceUniformly (const TriangleMesh& mesh, double area_per_sample, std::uint64_t seed,
                        const std::vector<bool>& excluded = {});

} // namespace morphreg
