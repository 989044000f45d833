// SPDX-License-Identifier: BSD-3-Clause
// `morphreg demo`: the main job end to end on the built-in data. Generates the synthetic population, builds a
// 7-region model from it, simulates a scan of a head not in the population, registers the model to the scan and
// writes the fitted mesh, the JSON report and a PNG overlay, with the fit's error against the true head.
#include "commands.h"
#include "option_checks.h"
#include "pipeline.h"
#include "progress.h"
#include "provenance.h"
#include "scanner_options.h"

#include <morphreg/synthetic/population_files.h>
#include <morphreg/visualization/x_display.h>

#include <chrono>
#include <iomanip>
#include <iostream>
#include <memory>

namespace morphreg
{
namespace tools
{
namespace
{
struct DemoOptions
{
  std::string out = "out/demo";
  int count = 150;
  int resolution = 40;
  std::uint64_t seed = 1;
  int model_components = 20;
  bool screenshot = true;
  bool convergence_plot = false;
  bool use_landmarks = false;
  bool quiet = false;
  synthetic::ScanSimulator::Parameters scanner;
  RegisterOptions registration;
};

/** Scans the held-out head into <out>/scan: scan.pcd with its truth (scan_truth.json, scan_truth.ply) and
 *  landmarks (scan_landmarks.json). */
void
writeSubjectScan (const DemoOptions& options, const synthetic::HeadGenerator& generator, std::uint64_t subject_seed)
{
  const synthetic::ScanSimulator scanner (options.scanner);
  const synthetic::SyntheticHead subject = generator.sample (subject_seed);
  const synthetic::SimulatedScan scan = scanner.scan (subject.mesh, subject_seed);
  synthetic::writeScanFiles (options.out + "/scan", "scan", scan, subject.mesh, generator.landmarks (),
                             provenanceJson ());
  if (!options.quiet)
    std::cout << "scanned a held-out head (seed " << subject_seed << "): " << scan.cloud->size () << " points, "
              << scan.num_outliers << " outliers\n";
}

/** The population's heads and annotations written into \a directory, with their progress. */
void
writeDemoPopulation (const DemoOptions& options, const synthetic::HeadGenerator& generator,
                     const std::string& directory)
{
  const Progress progress ("writing heads", options.count, options.quiet);
  synthetic::writePopulationFiles (directory, generator, generator.population (options.count, options.seed),
                                   options.seed, provenanceJson (),
                                   [&progress] (std::size_t done) { progress.step (static_cast<int> (done)); });
  progress.finish ();
}

void
runDemo (DemoOptions options)
{
  const auto start = std::chrono::steady_clock::now ();
  const synthetic::ScanSimulator check_scanner (options.scanner); // bad scanner settings fail before any work
  if (options.screenshot || options.convergence_plot)
    requireXDisplay ("demo (its overlay screenshot and plot; scripts/demo.sh runs it under xvfb-run, --no-screenshot "
                     "skips them)");
  // Each step's outputs are committed when the step is complete (each later step reads them); report.json, written
  // last, marks a complete demo.
  const synthetic::HeadGenerator generator (options.resolution);
  const std::string population = options.out + "/population";
  OutputTransaction population_output ({}, {population});
  writeDemoPopulation (options, generator, population);
  population_output.commit (population + "/population.json");

  BuildModelOptions model;
  model.directory = population;
  model.regions = population + "/regions.json";
  model.landmark_vertices = population + "/landmark_vertices.json";
  model.out = options.out + "/model.h5";
  model.settings.max_components = options.model_components;
  model.quiet = options.quiet;
  buildModelFile (model);

  // The scanned subject is not in the population: head seed + count, the next one drawn.
  const std::uint64_t subject_seed = options.seed + static_cast<std::uint64_t> (options.count);
  OutputTransaction scan_output ({}, {options.out + "/scan"});
  writeSubjectScan (options, generator, subject_seed);
  scan_output.commit ();

  RegisterOptions& fit = options.registration;
  fit.scan = options.out + "/scan/scan.pcd";
  fit.model = model.out;
  fit.truth = options.out + "/scan/scan_truth.ply";
  fit.landmarks = options.use_landmarks ? options.out + "/scan/scan_landmarks.json" : "";
  fit.out = options.out + "/fitted.ply";
  fit.report = options.out + "/report.json";
  fit.screenshot = options.screenshot ? options.out + "/overlay.png" : "";
  fit.convergence_plot = options.convergence_plot ? options.out + "/convergence.png" : "";
  fit.quiet = options.quiet;
  const nlohmann::json report = registerScanFile (fit);

  const nlohmann::json& truth = report["truth_vertex_error_mm"];
  const double seconds = std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
  std::cout << "demo: " << options.count << " heads in " << population << ", model " << model.out << ", scan "
            << fit.scan << "\n      fitted mesh " << fit.out << ", report " << fit.report
            << (options.screenshot ? ", overlay " + fit.screenshot : std::string ()) << "\n"
            << "demo: fit error against the ground truth: vertex RMS " << std::fixed << std::setprecision (3)
            << truth["rms"].get<double> () << " mm over all " << truth["count"] << " vertices, "
            << truth["covered_by_scan"]["rms"].get<double> () << " mm over the " << truth["covered_by_scan"]["count"]
            << " the scan covers (" << std::setprecision (1) << seconds << " s in all)\n";
}
} // namespace

void
registerDemoCommand (CLI::App& app)
{
  auto options = std::make_shared<DemoOptions> ();
  CLI::App* command =
      app.add_subcommand ("demo", "population -> model -> scan of a new head -> registration, into --out-dir");
  command->add_option ("--out-dir", options->out, "output folder")->capture_default_str ();
  command->add_option ("-n,--count", options->count, "population size")
      ->check (inRange (2, 5000))
      ->capture_default_str ();
  command->add_option ("--seed", options->seed, "population seed")->capture_default_str ();
  command->add_option ("-r,--resolution", options->resolution, "mesh resolution (even, 20-44; 40 = 9602 vertices)")
      ->check (inRange (20, 44))
      ->capture_default_str ();
  command->add_option ("--model-components", options->model_components, "components per region kept in the model")
      ->check (positive ())
      ->capture_default_str ();
  command->add_flag ("--no-screenshot{false}", options->screenshot, "skip the PNG overlay (runs without X)");
  command->add_flag ("--convergence-plot", options->convergence_plot,
                     "plot the fit's RMS per iteration into <out>/convergence.png (needs X)");
  command->add_flag ("--use-landmarks", options->use_landmarks,
                     "start the registration from the scan's true landmarks instead of the coarse alignment");
  command->add_flag ("-q,--quiet", options->quiet, "no progress output");
  addScannerOptions (command, options->scanner);
  options->registration.components = {options->model_components}; // fit every component the model keeps
  addRegistrationOptions (command, options->registration);
  command->callback ([options] () { runDemo (*options); });
}

} // namespace tools
} // namespace morphreg
