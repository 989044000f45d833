// SPDX-License-Identifier: BSD-3-Clause
// `morphreg synth`: the built-in synthetic head population and simulated scans of it, written to disk.
#include "commands.h"
#include "option_checks.h"
#include "progress.h"
#include "provenance.h"
#include "scanner_options.h"

#include <morphreg/common/landmarks.h>
#include <morphreg/io/output_transaction.h>
#include <morphreg/synthetic/population_files.h>

#include <cmath>
#include <iostream>
#include <memory>

namespace morphreg
{
namespace tools
{
namespace
{
struct SynthOptions
{
  std::string out = "out/synth";
  int count = 20;
  std::uint64_t seed = 1;
  int resolution = 40;
  int scans = 0;
  int photos = 0;
  bool quiet = false;
  synthetic::ScanSimulator::Parameters scanner;
};

/** Profile and frontal photo annotations of the first options.photos heads, each nodding by 5 degrees. */
void
writeHeadPhotos (const SynthOptions& options, const synthetic::HeadGenerator& generator,
                 const std::vector<synthetic::SyntheticHead>& heads)
{
  synthetic::PhotoSimulator::Parameters camera;
  camera.rotation = Eigen::AngleAxisd (5.0 * M_PI / 180.0, Eigen::Vector3d::UnitX ()).toRotationMatrix ();
  const synthetic::PhotoSimulator simulator (camera);
  const LandmarkVertices frontal = frontalLandmarks (generator.landmarks ());
  for (int i = 0; i < options.photos; ++i) {
    const auto& head = heads[static_cast<std::size_t> (i)];
    const std::uint64_t seed = options.seed + static_cast<std::uint64_t> (i);
    synthetic::writePhotoFiles (options.out, "photo_" + std::to_string (i),
                                simulator.photograph (head.mesh.vertices, frontal, generator.profileLine (), seed),
                                static_cast<std::size_t> (i), provenanceJson ());
  }
}

void
runSynth (const SynthOptions& options)
{
  const synthetic::ScanSimulator scanner (options.scanner); // bad scanner settings fail before anything is written
  // Every file goes into the folder at the end, the manifest population.json last: a folder with it is complete.
  OutputTransaction output ({}, {options.out});
  const synthetic::HeadGenerator generator (options.resolution);
  const std::vector<synthetic::SyntheticHead> heads = generator.population (options.count, options.seed);
  const Progress writing ("writing heads", options.count, options.quiet);
  synthetic::writePopulationFiles (options.out, generator, heads, options.seed, provenanceJson (),
                                   [&writing] (std::size_t done) { writing.step (static_cast<int> (done)); });
  writing.finish ();
  const Progress progress ("scanning heads", options.scans, options.quiet);
  for (int i = 0; i < options.scans; ++i) {
    const std::string name = "scan_" + std::to_string (i);
    const TriangleMesh& head = heads[static_cast<std::size_t> (i)].mesh;
    synthetic::writeScanFiles (options.out, name, scanner.scan (head, options.seed + i), head, generator.landmarks (),
                               provenanceJson ());
    progress.step (i + 1);
  }
  if (options.scans > 0)
    progress.finish ();
  writeHeadPhotos (options, generator, heads);
  output.commit (options.out + "/population.json");
  std::cout << "wrote " << options.count << " heads, " << options.scans << " scans and " << options.photos
            << " photo pairs to " << options.out << '\n';
}
} // namespace

void
registerSynthCommand (CLI::App& app)
{
  auto options = std::make_shared<SynthOptions> ();
  CLI::App* command =
      app.add_subcommand ("synth", "generate synthetic heads (PLY + population.json) and scans of them");
  command->add_option ("--out-dir", options->out, "output folder")->capture_default_str ();
  command->add_option ("-n,--count", options->count, "number of heads")
      ->check (inRange (1, 5000))
      ->capture_default_str ();
  command->add_option ("--seed", options->seed, "seed of the first head (head i uses seed + i)")
      ->capture_default_str ();
  command->add_option ("-r,--resolution", options->resolution, "mesh resolution (even, 20-44; 40 = 9602 vertices)")
      ->check (inRange (20, 44))
      ->capture_default_str ();
  command->add_option ("--scans", options->scans, "simulate scans of the first N heads")
      ->check (nonNegative ())
      ->capture_default_str ();
  command
      ->add_option ("--photos", options->photos,
                    "annotated profile and frontal photos of the first N heads (for fit-photos)")
      ->check (nonNegative ())
      ->capture_default_str ();
  command->add_flag ("-q,--quiet", options->quiet, "no progress output");
  addScannerOptions (command, options->scanner);
  command->callback ([options] () {
    if (options->scans > options->count)
      throw CLI::ValidationError ("--scans", "cannot scan more heads than --count");
    if (options->photos > options->count)
      throw CLI::ValidationError ("--photos", "cannot photograph more heads than --count");
    runSynth (*options);
  });
}

} // namespace tools
} // namespace morphreg
