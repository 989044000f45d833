// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// How many samples (heads, poses) an accuracy suite runs.
#include <algorithm>
#include <cstdlib>

namespace morphreg
{
namespace test
{
/** \brief \a count, or at most MORPHREG_TEST_SAMPLES (from the environment) when that is set: `scripts/check.sh
 *  sanitize` sets it, since under the sanitizers a fit runs 10 to 30 times slower and every sample runs the same code
 *  (the sanitizers look for memory and undefined-behaviour errors, not accuracy). The suites' per-sample requirements
 *  hold for each sample run; their aggregates are taken over the samples run. */
inline int
sampleCount (int count)
{
  const char* cap = std::getenv ("MORPHREG_TEST_SAMPLES");
  return cap ? std::clamp (std::atoi (cap), 1, count) : count;
}
} // namespace test
} // namespace morphreg
