// SPDX-License-Identifier: BSD-3-Clause
// `morphreg merge-summaries`: the summaries of the shards of a batch registration (register --scans --shard I/N,
// e.g. a Slurm job array) combined into the summary one run over every scan writes.
#include "commands.h"
#include "provenance.h"

#include <morphreg/common/error.h>
#include <morphreg/io/output_plan.h>
#include <morphreg/io/output_transaction.h>
#include <morphreg/pipeline/batch_provenance.h>
#include <morphreg/pipeline/batch_summary.h>

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
    throw FormatError (file + ": \"shard\" is '" + shard + "', not a shard I/N of register --shard");
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

/** Every shard I of N exactly once, all of one run, and no scan in two of them; errors name the files. */
std::vector<ScanSummary>
mergeShards (const std::vector<std::string>& files, nlohmann::json& run)
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
      throw InvalidInputError ("merge-summaries: shard " + std::to_string (index) + "/" +
                               std::to_string (shards.count) + " is missing (its summary.shard-" +
                               std::to_string (index) + "-of-" + std::to_string (shards.count) + ".json)");
  run = shards.run;
  return rows;
}

void
runMerge (const MergeOptions& options)
{
  const std::vector<std::string> files =
      options.summaries.empty () ? shardSummariesIn (options.out_dir) : options.summaries;
  const std::string base = (fs::path (options.out_dir) / "summary").string ();
  OutputPlan plan;
  for (const std::string& file : files)
    plan.addInput (file, "a shard summary");
  plan.addOutput (base + ".csv", "the merged summary");
  plan.addOutput (base + ".json", "the merged summary");
  OutputTransaction outputs (plan.outputs (), {options.out_dir}); // creates --out-dir; a refused run removes it
  plan.check ();
  nlohmann::json run;
  const std::vector<ScanSummary> rows = mergeShards (files, run);
  writeSummary (base, rows, "all", run, {{"morphreg", provenanceJson ()}});
  outputs.commit ();
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
