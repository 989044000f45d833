// SPDX-License-Identifier: BSD-3-Clause
// `morphreg merge-summaries`: the summaries of the shards of a batch registration (register --scans --shard I/N,
// e.g. a Slurm job array) combined into the summary one run over every scan writes.
#include "batch_summary.h"
#include "commands.h"

#include <morphreg/common/error.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <regex>

namespace morphreg
{
namespace tools
{
namespace
{
namespace fs = std::filesystem;

struct MergeOptions
{
  std::string out_dir;
  std::vector<std::string> summaries; ///< empty: every OUT/summary.shard-I-of-N.json
};

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
    throw IoError (directory + ": no shard summaries (summary.shard-I-of-N.json, written by register --shard)");
  std::sort (files.begin (), files.end ());
  return files;
}

/** Every shard I of N exactly once, and no scan in two of them; errors name the files. */
std::vector<ScanSummary>
mergeShards (const std::vector<std::string>& files)
{
  std::map<int, std::string> shards;
  int count = 0;
  std::map<std::string, std::string> owner; // scan id -> file
  std::vector<ScanSummary> rows;
  for (const std::string& file : files) {
    std::string shard;
    const std::vector<ScanSummary> part = readSummary (file, &shard);
    int index = -1, of = 0;
    if (std::sscanf (shard.c_str (), "%d/%d", &index, &of) != 2 || index < 0 || index >= of)
      throw FormatError (file + ": \"shard\" is '" + shard + "', not a shard I/N of register --shard");
    if (count != 0 && of != count)
      throw InvalidInputError (file + ": shard " + shard + " of " + std::to_string (of) + ", but " +
                               shards.begin ()->second + " is one of " + std::to_string (count));
    count = of;
    if (const auto [it, inserted] = shards.emplace (index, file); !inserted)
      throw InvalidInputError (file + ": shard " + shard + " given twice (also " + it->second + ")");
    for (const ScanSummary& row : part) {
      if (const auto [it, inserted] = owner.emplace (row.id, file); !inserted)
        throw InvalidInputError (file + ": scan '" + row.id + "' is also in " + it->second);
      rows.push_back (row);
    }
  }
  for (int index = 0; index < count; ++index)
    if (!shards.count (index))
      throw InvalidInputError ("merge-summaries: shard " + std::to_string (index) + "/" + std::to_string (count) +
                               " is missing (its summary.shard-" + std::to_string (index) + "-of-" +
                               std::to_string (count) + ".json)");
  return rows;
}

void
runMerge (const MergeOptions& options)
{
  const std::vector<std::string> files =
      options.summaries.empty () ? shardSummariesIn (options.out_dir) : options.summaries;
  const std::vector<ScanSummary> rows = mergeShards (files);
  const std::string base = (fs::path (options.out_dir) / "summary").string ();
  writeSummary (base, rows, "all");
  const auto failed =
      std::count_if (rows.begin (), rows.end (), [] (const ScanSummary& r) { return r.status != "ok"; });
  std::cout << "merged " << files.size () << " shard summaries: " << rows.size () << " scans, " << failed
            << " not ok; wrote " << base << ".csv and " << base << ".json\n";
}
} // namespace

void
registerMergeSummariesCommand (CLI::App& app)
{
  auto options = std::make_shared<MergeOptions> ();
  CLI::App* command = app.add_subcommand ("merge-summaries", "combine the shard summaries of register --scans "
                                                             "--shard into one summary.csv / summary.json");
  command
      ->add_option ("--out-dir", options->out_dir,
                    "folder of the merged summary (and, without files, of the "
                    "shard summaries)")
      ->required ();
  command->add_option ("summaries", options->summaries,
                       "shard summaries (default: every "
                       "OUT/summary.shard-I-of-N.json)");
  command->callback ([options] () { runMerge (*options); });
}

} // namespace tools
} // namespace morphreg
