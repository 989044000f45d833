// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The resampling suites' score: how far the resampled vertices in one state lie from the true surface.
#include <morphreg/mesh/triangle_locator.h>
#include <morphreg/resampling/scan_resampler.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace morphreg
{
namespace test
{
/** \brief RMS distance (mm) from the vertices of \a result in \a state (those \a counted, when given) to \a truth's
 *  surface. NaN when no vertex is scored: a resampler that observes nothing meets no bound. */
inline double
rmsToSurface (const ResamplingResult& result, ResampledVertex state, const TriangleLocator& truth,
              const std::function<bool (Eigen::Index)>& counted = {})
{
  double sum = 0.0;
  int count = 0;
  for (Eigen::Index v = 0; v < result.mesh.numVertices (); ++v)
    if (result.state[static_cast<size_t> (v)] == state && (!counted || counted (v))) {
      sum += std::pow (truth.closestPoint (result.mesh.vertices.col (v)).distance, 2);
      ++count;
    }
  return count ? std::sqrt (sum / count) : std::numeric_limits<double>::quiet_NaN ();
}

/** \brief \a result with its vertices put back at the reference's (\a reference, in the same states): what a
 *  resampler that moves nothing returns, the no-op the resampled figures are compared with. */
inline ResamplingResult
referenceInPlace (const ResamplingResult& result, const TriangleMesh& reference)
{
  ResamplingResult unmoved = result;
  unmoved.mesh = reference;
  unmoved.displacement.setZero ();
  return unmoved;
}
/** \brief The share of \a result's vertices in the observed state, counted from the states (not the statistics). */
inline double
observedShare (const ResamplingResult& result)
{
  const auto observed = std::count (result.state.begin (), result.state.end (), ResampledVertex::observed);
  return static_cast<double> (observed) / static_cast<double> (result.state.size ());
}

/** \brief What a resampler that observes nothing and fills everything returns: \a reference, every vertex filled. */
inline ResamplingResult
nothingObserved (const ResamplingResult& result, const TriangleMesh& reference)
{
  ResamplingResult nothing = referenceInPlace (result, reference);
  std::fill (nothing.state.begin (), nothing.state.end (), ResampledVertex::filled);
  return nothing;
}
} // namespace test
} // namespace morphreg
