// SPDX-License-Identifier: BSD-3-Clause
// `morphreg merge-summaries`: the summaries of the shards of a batch registration (register --scans --shard I/N,
// e.g. a Slurm job array) combined into the summary one run over every scan writes.
#include "commands.h"
#include "provenance.h"

#include <morphreg/common/error.h>
#include <morphreg/io/output_plan.h>
#include <morphreg/io/output_transaction.h>
#include <morphreg/pipeline/batch_summary_merge.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

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
  const MergedSummary merged = mergeShardSummaries (files);
  const std::vector<ScanSummary>& rows = merged.rows;
  writeSummary (base, rows, "all", merged.run, {{"morphreg", provenanceJson ()}});
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
