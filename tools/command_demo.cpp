// `morphreg demo`: the main job on the built-in data. Generates the synthetic population and a simulated
// scan of a held-out head, writes them with a JSON report.
#include "commands.h"
#include "json_report.h"
#include "scanner_options.h"
#include "synthetic_output.h"

#include <morphreg/common/error.h>
#include <morphreg/io/mesh_io.h>

#include <chrono>
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
  int count = 50;
  std::uint64_t seed = 1;
  bool quiet = false;
  synthetic::ScanSimulator::Parameters scanner;
};

double
secondsSince (std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
}

void
runDemo (DemoOptions options)
{
  const auto start = std::chrono::steady_clock::now ();
  options.scanner.range_mesh = true;
  const synthetic::ScanSimulator scanner (options.scanner); // bad scanner settings fail before anything is written
  const synthetic::HeadGenerator generator;
  const auto heads = generator.population (options.count, options.seed);
  writePopulation (options.out + "/population", generator, heads, options.seed, options.quiet);

  // The scanned subject is not in the population: head seed + count, the next one drawn.
  const std::uint64_t subject_seed = options.seed + static_cast<std::uint64_t> (options.count);
  const synthetic::SyntheticHead subject = generator.sample (subject_seed);
  const synthetic::SimulatedScan scan = scanner.scan (subject.mesh, subject_seed);
  makeDirectory (options.out + "/scan");
  saveTriangleMesh (options.out + "/scan/subject_truth.ply", subject.mesh);
  const nlohmann::json scan_summary = writeScan (options.out + "/scan", "scan", scan);

  const nlohmann::json report = {{"units", "mm"},
                                 {"population", {{"directory", "population"}, {"count", options.count},
                                                 {"seed", options.seed}, {"vertices", generator.numVertices ()},
                                                 {"triangles", generator.triangles ().cols ()}}},
                                 {"scan", scan_summary},
                                 {"subject_seed", subject_seed},
                                 {"seconds", secondsSince (start)}};
  const std::string report_path = options.out + "/demo_report.json";
  writeJsonReport (report_path, report);
  std::cout << "demo: " << options.count << " heads in " << options.out << "/population, scan of a held-out head ("
            << scan.cloud->size () << " points, " << scan.num_outliers << " outliers) in " << options.out
            << "/scan, report " << report_path << '\n';
}
} // namespace

void
registerDemoCommand (CLI::App& app)
{
  auto options = std::make_shared<DemoOptions> ();
  CLI::App* command = app.add_subcommand ("demo", "run the main job on the built-in synthetic data");
  command->add_option ("-o,--out", options->out, "output directory")->capture_default_str ();
  command->add_option ("-n,--count", options->count, "population size")->check (CLI::Range (2, 5000))
      ->capture_default_str ();
  command->add_option ("-s,--seed", options->seed, "population seed")->capture_default_str ();
  command->add_flag ("-q,--quiet", options->quiet, "no progress output");
  addScannerOptions (command, options->scanner);
  command->callback ([options] () { runDemo (*options); });
}

} // namespace tools
} // namespace morphreg
