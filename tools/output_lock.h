// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A batch run's claim on its share of an output folder: a lock file per shard, so that the shards of one job array
// work side by side while a second run on the same share, or an unrelated run on the same folder, is refused as
// long as the first one lives. A lock whose process is gone (killed, a crashed node) is recognised and taken over.
#include <ostream>
#include <string>

namespace morphreg
{
namespace tools
{
/** Who holds a lock, as recorded in the lock file. */
struct LockOwner
{
  long pid = 0;
  std::string host;
  std::string process_start; ///< /proc/<pid>/stat's start time: a pid reused by another process is not the owner
  std::string started;       ///< when the lock was taken (UTC)
  std::string run;           ///< the fingerprint of the run's study (RunRecord::fingerprint)
  int shards = 1;            ///< the run's shard count (1: the whole study)

  /** "pid 123 on host node7, since 2026-01-02 03:04:05 UTC" */
  std::string
  text () const;
};

/** The lock of one run's share of \a out_dir, held while the object lives (removed by the destructor, and by
 *  releaseOutputLockNow() from a signal handler). */
class OutputLock
{
public:
  /** Takes the lock OUT/.morphreg.lock (one run over the whole study, \a shards 1) or
   *  OUT/.morphreg.shard-I-of-N.lock. IoError naming the lock file and its owner if a live process holds it, or if
   *  a live lock of the folder belongs to a run that is not another shard of the same study (another \a run
   *  fingerprint or shard count); a stale lock (its process is gone) of this share is taken over, saying so on
   *  \a out. */
  OutputLock (const std::string& out_dir, int shard, int shards, const std::string& run, std::ostream& out);
  ~OutputLock ();
  OutputLock (const OutputLock&) = delete;
  OutputLock&
  operator= (const OutputLock&) = delete;

  const std::string&
  path () const
  {
    return path_;
  }

private:
  std::string path_;
};

/** Removes the lock this process holds, if any; async-signal-safe (for SIGTERM: a cancelled Slurm task). */
void
releaseOutputLockNow ();
} // namespace tools
} // namespace morphreg
