// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file batch_shard.h
 *  \brief One share of a study for one machine of a job array (see manifestShard in io/scan_manifest.h): which it
 *  is, the names of its files, and the share a user names ("I/N", or "auto" in a Slurm job array).
 */
#include <string>

namespace morphreg
{
/** \brief Share \a index of \a count of a study's scans (0 <= index < count); 0 of 1 is the whole study. */
struct BatchShard
{
  int index = 0; ///< this share, 0-based
  int count = 1; ///< the number of shares

  /** \brief The share for messages and summaries.
   *  \return "I/N" */
  std::string
  text () const
  {
    return std::to_string (index) + "/" + std::to_string (count);
  }

  /** \brief What names the share's files (its lock, its summary).
   *  \return "shard-I-of-N", or "all" for the whole study */
  std::string
  tag () const
  {
    return count > 1 ? "shard-" + std::to_string (index) + "-of-" + std::to_string (count) : std::string ("all");
  }
};

/** \brief The share \a text names: "I/N" (0 <= I < N), "auto" for this task of a Slurm job array (its
 *  SLURM_ARRAY_TASK_ID less SLURM_ARRAY_TASK_MIN, of SLURM_ARRAY_TASK_COUNT), or empty for the whole study.
 *  \param[in] text the share as a user writes it
 *  \return the share
 *  \throws InvalidInputError naming \a text when it is neither, or the Slurm variable that is unset or not a number */
BatchShard
parseBatchShard (const std::string& text);
} // namespace morphreg
