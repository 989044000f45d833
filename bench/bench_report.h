// SPDX-License-Identifier: BSD-3-Clause
// What the benchmarks report besides their times: the threads each case runs on (counter "threads"), so that every
// ratio in bench/RESULTS.md can be read per core (per-core ratio = wall-time ratio x the baseline's threads / ours),
// and, where a benchmark has no PCL/VTK baseline, a label that says so.
#pragma once

#include <benchmark/benchmark.h>
#include <omp.h>

namespace morphreg
{
namespace bench
{
/** Registers a case's times as wall-clock milliseconds with the process's CPU time over all its threads beside them:
 *  BENCHMARK (BM_X)->Apply (wallAndProcessCpuMs). */
inline void
wallAndProcessCpuMs (benchmark::internal::Benchmark* b)
{
  b->Unit (benchmark::kMillisecond)->UseRealTime ()->MeasureProcessCPUTime ();
}

/** The case runs on the OpenMP threads this process may use (morphreg's loops, and Eigen's products). */
inline void
reportOpenMpThreads (benchmark::State& state)
{
  state.counters["threads"] = omp_get_max_threads ();
}

/** The case runs on \a threads threads whatever OMP_NUM_THREADS says (PCL's ICP, VTK's serial filters: 1). */
inline void
reportThreads (benchmark::State& state, int threads)
{
  state.counters["threads"] = threads;
}

/** A case of morphreg on its OpenMP threads in a benchmark with no external baseline (PCL and VTK have none for
 *  the job): it is compared with morphreg itself, and its label says so. */
inline void
reportNoExternalBaseline (benchmark::State& state)
{
  reportOpenMpThreads (state);
  state.SetLabel ("no external baseline");
}

/** While it lives, morphreg's OpenMP loops run on \a threads threads (0: as many as before); reports them. */
class OpenMpThreads
{
public:
  OpenMpThreads (benchmark::State& state, int threads) : before_ (omp_get_max_threads ())
  {
    if (threads > 0)
      omp_set_num_threads (threads);
    reportOpenMpThreads (state);
  }
  ~OpenMpThreads ()
  {
    omp_set_num_threads (before_);
  }
  OpenMpThreads (const OpenMpThreads&) = delete;
  OpenMpThreads&
  operator= (const OpenMpThreads&) = delete;

private:
  int before_;
};
} // namespace bench
} // namespace morphreg
