// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/common/order_statistics.h>
#include <morphreg/mesh/surface_sampling.h>
#include <morphreg/mesh/triangle_locator.h>
#include <morphreg/registration/surface_distance.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace morphreg
{
namespace
{
/** Fills the statistics of \a result from its distances. */
void
summarise (SurfaceDistance& result)
{
  const auto n = static_cast<double> (result.distances.size ());
  result.mean = std::accumulate (result.distances.begin (), result.distances.end (), 0.0) / n;
  result.rms = std::sqrt (
      std::inner_product (result.distances.begin (), result.distances.end (), result.distances.begin (), 0.0) / n);
  result.max = *std::max_element (result.distances.begin (), result.distances.end ());
  result.median = percentile (result.distances, 0.5);
  result.percentile95 = percentile (result.distances, 0.95);
}
} // namespace

SurfaceDistance
surfaceDistance (const TriangleMesh& target, const TriangleMesh& fitted, const std::vector<bool>& excluded_target,
                 const SurfaceDistanceSettings& settings)
{
  const SurfaceSamples samples =
      sampleSurfaceUniformly (target, settings.area_per_sample, settings.seed, excluded_target);
  SurfaceDistance result = pointDistances (samples.points, fitted, settings.drop_boundary);
  if (result.distances.empty ())
    throw InvalidInputError ("surfaceDistance: every target sample reaches the fitted surface only at its boundary");
  return result;
}

SurfaceDistance
pointDistances (const Eigen::Matrix3Xd& points, const TriangleMesh& fitted, bool drop_boundary)
{
  const TriangleLocator locator (fitted);
  SurfaceDistance result;
  result.samples = static_cast<int> (points.cols ());
  std::vector<TriangleLocator::Hit> hits (points.cols ());
#pragma omp parallel for schedule(static)
  for (Eigen::Index i = 0; i < points.cols (); ++i)
    hits[static_cast<size_t> (i)] = locator.closestPoint (points.col (i));
  for (const auto& hit : hits) {
    if (drop_boundary && hit.on_boundary)
      ++result.dropped_on_boundary;
    else {
      result.distances.push_back (hit.distance);
      result.fitted_triangles.push_back (hit.triangle);
    }
  }
  if (!result.distances.empty ())
    summarise (result);
  return result;
}

SurfaceDistance
surfaceDistanceOver (const SurfaceDistance& distance, const std::vector<bool>& triangles)
{
  SurfaceDistance subset;
  subset.samples = distance.samples;
  subset.dropped_on_boundary = distance.dropped_on_boundary;
  for (size_t i = 0; i < distance.distances.size (); ++i) {
    const int triangle = distance.fitted_triangles.at (i);
    if (triangle < 0 || static_cast<size_t> (triangle) >= triangles.size ())
      throw InvalidInputError ("surfaceDistanceOver: " + std::to_string (triangles.size ()) +
                               " triangle flags, but a sample lies on fitted triangle " + std::to_string (triangle));
    if (triangles[static_cast<size_t> (triangle)]) {
      subset.distances.push_back (distance.distances[i]);
      subset.fitted_triangles.push_back (triangle);
    }
  }
  if (subset.distances.empty ())
    throw InvalidInputError ("surfaceDistanceOver: no sample lies on the flagged triangles");
  summarise (subset);
  return subset;
}

} // namespace morphreg
