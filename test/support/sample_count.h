// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// How many samples (heads, poses) an accuracy suite runs.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <set>

namespace morphreg
{
namespace test
{
/** \brief \a count, or at most MORPHREG_TEST_SAMPLES (from the environment) when that is set: `scripts/check.sh
 *  sanitize` sets it, since under the sanitizers a fit runs 10 to 30 times slower and every sample runs the same code
 *  (the sanitizers look for memory and undefined-behaviour errors, not accuracy). The suites' per-sample requirements
 *  and worst cases hold for each sample run; a median over the suite's samples is asserted on the whole suite only
 *  (suiteMedianUpperBound, accuracy_bound.h). A capped count is said on stdout (once per count), so that a shrunken
 *  suite never passes for the whole one. */
inline int
sampleCount (int count)
{
  const char* cap = std::getenv ("MORPHREG_TEST_SAMPLES");
  if (!cap)
    return count;
  const int capped = std::clamp (std::atoi (cap), 1, count);
  static std::mutex mutex;
  static std::set<int> said;
  const std::lock_guard<std::mutex> lock (mutex);
  if (capped < count && said.insert (count).second)
    std::printf ("[ samples ] MORPHREG_TEST_SAMPLES=%s: %d of the suite's %d samples run; its aggregate figures are "
                 "not the suite's\n",
                 cap, capped, count);
  return capped;
}
} // namespace test
} // namespace morphreg
