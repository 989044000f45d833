// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file batch_summary_merge.h
 *  \brief The summaries of the shards of a batch registration (batch_registration.h with a shard, e.g. one task of a
 *  Slurm job array each) combined into the summary one run over every scan writes: every shard exactly once, all
 *  made by one run (the same study, model, settings and version), no scan in two of them.
 */
#include <morphreg/pipeline/batch_summary.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace morphreg
{
/** \brief The shard summaries of a study merged. */
struct MergedSummary
{
  std::vector<ScanSummary> rows; ///< every scan of every shard
  nlohmann::json run;            ///< the record of the run that made them (RunRecord::summary())
  int shards = 0;                ///< the number of shards
};

/** \brief The shard summaries in \a folder: every summary.shard-I-of-N.json, sorted by name; IoError naming the
 *  folder when it is missing or holds none.
 *  \param[in] folder the output folder of the shards
 *  \return the files */
std::vector<std::string>
shardSummariesIn (const std::string& folder);

/** \brief Merges the shard summaries \a files. Errors name the files: one that is not a summary, a shard that is
 *  not I/N, of another count, given twice or made by another run (another model, settings, version or study), a
 *  scan in two shards, a shard missing.
 *  \param[in] files the shard summaries (readSummary)
 *  \return the rows and the run */
MergedSummary
mergeShardSummaries (const std::vector<std::string>& files);
} // namespace morphreg
