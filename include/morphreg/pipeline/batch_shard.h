// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file batch_shard.h
 *  \brief One share of a study for one machine of a job array (see manifestShard in io/scan_manifest.h): which it
 *  is, and the names of its files.
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
} // namespace morphreg
