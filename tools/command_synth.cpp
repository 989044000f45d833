// SPDX-License-Identifier: BSD-3-Clause
// `morphreg synth`: the built-in synthetic head population and simulated scans of it, written to disk.
#include "commands.h"
#include "option_checks.h"
#include "progress.h"
#include "provenance.h"
#include "scanner_options.h"

#include <morphreg/io/output_transaction.h>
#include <morphreg/synthetic/population_files.h>

#include <iostream>
#include <memory>
#include <optional>
#include <string>

namespace morphreg
{
namespace tools
{
namespace
{
struct SynthOptions
{
  std::string out = "out/synth";
  synthetic::SyntheticStudySettings study;
  bool quiet = false;
};

void
runSynth (const SynthOptions& options)
{
  // Every file goes into the folder at the end, the manifest population.json last: a folder with it is complete.
  OutputTransaction output ({}, {options.out});
  std::optional<Progress> progress;
  std::string stage;
  const auto told = [&] (const std::string& name, int done, int count) {
    if (name != stage) {
      if (progress)
        progress->finish ();
      progress.emplace (name, count, options.quiet);
      stage = name;
    }
    progress->step (done);
  };
  synthetic::writeSyntheticStudy (options.out, options.study, provenanceJson (), told);
  if (progress)
    progress->finish ();
  output.commit (options.out + "/population.json");
  std::cout << "wrote " << options.study.count << " heads, " << options.study.scans << " scans and "
            << options.study.photos << " photo pairs to " << options.out << '\n';
}
} // namespace

void
registerSynthCommand (CLI::App& app)
{
  auto options = std::make_shared<SynthOptions> ();
  CLI::App* command =
      app.add_subcommand ("synth", "generate synthetic heads (PLY + population.json) and scans of them");
  command->add_option ("--out-dir", options->out, "output folder")->capture_default_str ();
  command->add_option ("-n,--count", options->study.count, "number of heads")
      ->check (inRange (1, 5000))
      ->capture_default_str ();
  command->add_option ("--seed", options->study.seed, "seed of the first head (head i uses seed + i)")
      ->capture_default_str ();
  command
      ->add_option ("-r,--resolution", options->study.resolution, "mesh resolution (even, 20-44; 40 = 9602 vertices)")
      ->check (inRange (20, 44))
      ->capture_default_str ();
  command->add_option ("--scans", options->study.scans, "simulate scans of the first N heads")
      ->check (nonNegative ())
      ->capture_default_str ();
  command
      ->add_option ("--photos", options->study.photos,
                    "annotated profile and frontal photos of the first N heads (for fit-photos)")
      ->check (nonNegative ())
      ->capture_default_str ();
  command->add_flag ("-q,--quiet", options->quiet, "no progress output");
  addScannerOptions (command, options->study.scanner);
  command->callback ([options] () { runSynth (*options); });
}

} // namespace tools
} // namespace morphreg
