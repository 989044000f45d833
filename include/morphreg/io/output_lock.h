// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file output_lock.h
 *  \brief A batch run's claim on its share of an output folder: a lock file per shard, so that the shards of one job
 *  array work side by side while a second run on the same share, or an unrelated run on the same folder, is refused
 *  as long as the first one lives. A lock whose process is gone (killed, a crashed node) is recognised and taken
 *  over.
 */
#include <ostream>
#include <string>

namespace morphreg
{
/** \brief Who holds a lock, as recorded in the lock file. */
struct LockOwner
{
  long pid = 0;              ///< the owning process
  std::string host;          ///< the host it runs on
  std::string process_start; ///< /proc/PID/stat's start time: a pid reused by another process is not the owner
  std::string started;       ///< when the lock was taken (UTC)
  std::string run;           ///< the fingerprint of the run's study
  int shards = 1;            ///< the run's shard count (1: the whole study)

  /** \brief The owner for messages.
   *  \return e.g. "pid 123 on host node7, since 2026-01-02 03:04:05 UTC" */
  std::string
  text () const;
};

/** \brief The lock of one run's share of an output folder, held while the object lives (removed by the destructor,
 *  and by releaseOutputLockNow() from a signal handler). */
class OutputLock
{
public:
  /** \brief Takes the lock OUT/.morphreg.lock (one run over the whole study, \a shards 1) or
   *  OUT/.morphreg.shard-I-of-N.lock. IoError naming the lock file and its owner if a live process holds it, or if
   *  a live lock of the folder belongs to a run that is not another shard of the same study (another \a run
   *  fingerprint or shard count); a stale lock (its process is gone) of this share is taken over, saying so on
   *  \a out.
   *  \param[in] out_dir the output folder
   *  \param[in] shard this run's shard (0-based)
   *  \param[in] shards the number of shards (1: the whole study)
   *  \param[in] run the fingerprint of the run's study
   *  \param[in] out where a taken-over stale lock is reported */
  OutputLock (const std::string& out_dir, int shard, int shards, const std::string& run, std::ostream& out);
  ~OutputLock ();
  OutputLock (const OutputLock&) = delete; ///< not copyable: one owner per lock file
  OutputLock&
  operator= (const OutputLock&) = delete; ///< not copyable: one owner per lock file

  /** \brief The lock file.
   *  \return its path */
  const std::string&
  path () const
  {
    return path_;
  }

private:
  std::string path_;
};

/** \brief Removes the lock this process holds, if any; async-signal-safe (for SIGTERM: a cancelled Slurm task). */
void
releaseOutputLockNow ();
} // namespace morphreg
