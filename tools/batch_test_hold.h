// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// TEST-ONLY fault-injection point of `register --scans`, so that the batch tests (test/scripts/cli/batch.sh, the
// Slurm test) kill, interrupt or cancel a run at a known scan instead of racing it against a timer. Not a user
// feature: it is read from the environment only, and is not in --help.
//
//   MORPHREG_BATCH_TEST_HOLD=N:DIR
//
// The worker that takes the run's scan number N (0-based, in the order the run takes them: with --jobs 1, after N
// scans have finished) first writes DIR/held.<share> (holding its pid), then waits, before registering that scan,
// until DIR/release.<share> exists, the run is interrupted (Ctrl-C), or 600 s have passed. <share> is "all" for a
// run over the whole study, "shard-I-of-N" for a shard, so that one task of a job array can be held alone.
#include <atomic>
#include <cstddef>
#include <string>

namespace morphreg
{
namespace tools
{
class BatchTestHold
{
public:
  /** The hold of \a share ("all" or "shard-I-of-N") from MORPHREG_BATCH_TEST_HOLD; inactive if it is unset.
   *  InvalidInputError naming the variable if it is not N:DIR. */
  explicit BatchTestHold (const std::string& share);

  /** Holds (see above) if \a index is the scan to hold at; returns at once otherwise. */
  void
  atScan (std::size_t index, const std::atomic<int>& interrupts) const;

private:
  long index_ = -1; ///< -1: no hold
  std::string held_, release_;
};
} // namespace tools
} // namespace morphreg
