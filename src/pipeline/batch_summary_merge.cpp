// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/pipeline/batch_provenance.h>
#include <morphreg/pipeline/batch_summary_merge.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <regex>

namespace morphreg
{
namespace
{
namespace fs = std::filesystem;

/** The shards read so far: the index -> file of each, their count, and the run they come from. */
struct ShardSet
{
  std::map<int, std::string> files;
  int count = 0;
  nlohmann::json run; ///< the first shard's record of its run (RunRecord::summary())
};

/** Adds \a file's shard \a shard (its text "I/N") made by \a run to \a set; errors name the files: a shard that is
 *  not I/N, of another count, given twice, or made by another run (another model, settings, version or study). */
void
addShard (ShardSet& set, const std::string& file, const std::string& shard, const nlohmann::json& run)
{
  int index = -1, of = 0;
  if (std::sscanf (shard.c_str (), "%d/%d", &index, &of) != 2 || index < 0 || index >= of)
    throw FormatError (file + ": \"shard\" is '" + shard + "', not a shard I/N");
  const std::string first = set.files.empty () ? std::string () : set.files.begin ()->second;
  if (set.count != 0 && of != set.count)
    throw InvalidInputError (file + ": shard " + shard + " of " + std::to_string (of) + ", but " + first +
                             " is one of " + std::to_string (set.count));
  if (set.count != 0 && run != set.run) {
    const std::string why = recordMismatch (set.run, run, "in " + first, "in " + file);
    throw InvalidInputError (file + ": made by another run than " + first + ": " +
                             (why.empty () ? "another list of scans (manifest)" : why));
  }
  set.count = of;
  set.run = run;
  if (const auto [it, inserted] = set.files.emplace (index, file); !inserted)
    throw InvalidInputError (file + ": shard " + shard + " given twice (also " + it->second + ")");
}

} // namespace

std::vector<std::string>
shardSummariesIn (const std::string& directory)
{
  std::error_code ec;
  if (!fs::is_directory (directory, ec))
    throw IoError (directory + ": no such folder");
  const std::regex name ("summary\\.shard-[0-9]+-of-[0-9]+\\.json");
  std::vector<std::string> files;
  for (const auto& item : fs::directory_iterator (directory))
    if (std::regex_match (item.path ().filename ().string (), name))
      files.push_back (item.path ().string ());
  if (files.empty ())
    throw IoError (directory +
                   ": no shard summaries (summary.shard-I-of-N.json, written by the shards of a batch registration)");
  std::sort (files.begin (), files.end ());
  return files;
}

MergedSummary
mergeShardSummaries (const std::vector<std::string>& files)
{
  ShardSet shards;
  std::map<std::string, std::string> owner; // scan id -> file
  std::vector<ScanSummary> rows;
  for (const std::string& file : files) {
    std::string shard;
    nlohmann::json shard_run;
    const std::vector<ScanSummary> part = readSummary (file, &shard, &shard_run);
    addShard (shards, file, shard, shard_run);
    for (const ScanSummary& row : part) {
      if (const auto [it, inserted] = owner.emplace (row.id, file); !inserted)
        throw InvalidInputError (file + ": scan '" + row.id + "' is also in " + it->second);
      rows.push_back (row);
    }
  }
  for (int index = 0; index < shards.count; ++index)
    if (!shards.files.count (index))
      throw InvalidInputError ("shard " + std::to_string (index) + "/" + std::to_string (shards.count) +
                               " is missing (its summary.shard-" + std::to_string (index) + "-of-" +
                               std::to_string (shards.count) + ".json)");
  return {rows, shards.run, shards.count};
}

} // namespace morphreg
