// SPDX-License-Identifier: BSD-3-Clause
// `morphreg build-model`: meshes in correspondence (files, a folder, or the ICT-FaceKit model) -> a model file.
#include "build_model_console.h"
#include "commands.h"
#include "option_checks.h"
#include "pipeline.h"
#include "provenance.h"
#include "table_options.h"

#include <morphreg/common/error.h>
#include <morphreg/datasets/ict_facekit.h>
#include <morphreg/io/model_io.h>
#include <morphreg/io/output_plan.h>
#include <morphreg/io/scan_manifest.h>
#include <morphreg/model/model_builder_options.h>
#include <morphreg/pipeline/model_building.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

namespace morphreg
{
namespace tools
{
namespace
{
ModelBuildingOutcome
buildFromMeshes (const BuildModelOptions& options, ModelBuildingObserver& observer)
{
  MeshFolder folder;
  if (!options.directory.empty ())
    folder = readMeshFolder (options.directory);
  folder.files.insert (folder.files.end (), options.meshes.begin (), options.meshes.end ());
  ModelFromMeshes building ({options.settings, options.regions, options.landmark_vertices});
  building.setObserver (&observer);
  return building.build (folder);
}

ModelBuildingOutcome
buildFromIct (const BuildModelOptions& options)
{
  if (!options.quiet)
    std::cerr << "loading the ICT-FaceKit model from " << options.ict_directory << " and sampling "
              << options.ict.samples << " heads\n";
  const MorphableModel::Ptr ict = loadIctFaceKit (options.ict_directory);
  ModelFromIctSettings settings = options.ict;
  settings.builder = options.settings;
  return buildModelFromIct (*ict, options.ict_directory, settings);
}

/** Builds the model of options.from_scans with ModelFromScans, each scan registered with options.registration's
 *  model and resampled, its report, fit and resampled mesh and the study's summary.json written into
 *  \a report_dir; adds the registering model and the report folder to the outcome's source. */
ModelBuildingOutcome
buildFromScans (const BuildModelOptions& options, const std::string& report_dir)
{
  const ScanManifest scans = loadScanList (options.from_scans);
  ModelFromScansSettings settings;
  settings.builder = options.settings;
  settings.regions = options.regions;
  settings.landmark_vertices = options.landmark_vertices;
  settings.registration = options.registration;
  settings.resampling = options.resampling;
  ModelFromScans building (loadModelFile (options.registration.model, std::cout), settings);
  building.writeScanFilesInto (report_dir, options.registration.model, options.registration.colours,
                               {{"morphreg", provenanceJson ()}});
  BuildModelConsole console (options.quiet);
  building.setObserver (&console);
  ModelBuildingOutcome outcome = building.build (scans, options.from_scans);
  const std::size_t included = outcome.source["included"];
  std::cout << "build-model: " << included << " of " << scans.size () << " scans registered and resampled, "
            << scans.size () - included << " left out (reports in " << report_dir << ")\n";
  outcome.source["registering_model"] = options.registration.model;
  outcome.source["report_dir"] = report_dir;
  return outcome;
}

void
runBuildModel (const BuildModelOptions& options)
{
  const nlohmann::json summary = buildModelFile (options);
  std::cout << "wrote " << options.out << ": " << summary["vertices"] << " vertices, " << summary["regions"].size ()
            << " region(s), components per region " << summary["components"].dump () << ", " << summary["landmarks"]
            << " landmarks (" << summary["seconds"] << " s)\n";
}

/** The files and folders build-model reads, which its outputs must not overwrite. */
void
addInputs (const BuildModelOptions& options, OutputPlan& plan)
{
  for (const std::string& mesh : options.meshes)
    plan.addInput (mesh, "--mesh");
  if (!options.directory.empty ()) {
    plan.addInputFolder (options.directory, "--dir");
    for (const std::string& file : readMeshFolder (options.directory).files)
      plan.addInput (file, "a mesh of --dir");
  }
  if (!options.from_scans.empty ()) {
    for (const ScanEntry& entry : loadScanList (options.from_scans)) {
      plan.addInput (entry.scan, "the scan of id '" + entry.id + "'");
      plan.addInput (entry.landmarks, "the landmarks of id '" + entry.id + "'");
    }
    std::error_code ec;
    if (std::filesystem::is_directory (options.from_scans, ec))
      plan.addInputFolder (options.from_scans, "--from-scans");
    else
      plan.addInput (options.from_scans, "--from-scans");
    plan.addInput (options.registration.model, "--model");
  }
  plan.addInput (options.regions, "--regions");
  plan.addInput (options.landmark_vertices, "--landmark-vertices");
  plan.addInputFolder (options.ict_directory, "--from-ict");
}

/** Adds the ModelBuilder settings of the library's table (model_builder_options.h) to \a command. */
void
addModelBuilderOptions (CLI::App* command, ModelBuilderSettings& settings)
{
  for (const ModelBuilderOption& option : modelBuilderOptions ())
    addTableOption<ModelBuilderSettings> (command, settings, option);
}

} // namespace

nlohmann::json
buildModelFile (const BuildModelOptions& options)
{
  const auto start = std::chrono::steady_clock::now ();
  const std::string report_dir = options.report_dir.empty ()
                                     ? std::filesystem::path (options.out).replace_extension ().string () + "_scans"
                                     : options.report_dir;
  OutputPlan plan;
  addInputs (options, plan);
  plan.addOutput (options.out, "--out");
  if (!options.from_scans.empty ())
    for (const auto& [file, what] : ModelFromScans::scanFolderOutputs (loadScanList (options.from_scans), report_dir))
      plan.addOutput (file, what);
  // The report folder is made (and removed again on failure) by the transaction before the plan checks it.
  OutputTransaction outputs ({options.out}, options.from_scans.empty () ? std::vector<std::string> ()
                                                                        : std::vector<std::string>{report_dir});
  plan.check ();
  BuildModelConsole console (options.quiet);
  const ModelBuildingOutcome outcome = !options.from_scans.empty ()      ? buildFromScans (options, report_dir)
                                       : !options.ict_directory.empty () ? buildFromIct (options)
                                                                         : buildFromMeshes (options, console);
  outcome.model->setMetadata ({{"builder", "morphreg build-model"},
                               {"source", outcome.source.dump ()},
                               {"morphreg_version", MORPHREG_VERSION},
                               {"command_line", commandLine ()}});
  saveModel (options.out, *outcome.model);
  nlohmann::json summary = outcome.summary (options.settings);
  summary["file"] = options.out;
  summary["seconds"] = std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
  outputs.commit ((std::filesystem::path (report_dir) / "summary.json").string ());
  return summary;
}

/** The options of `--from-scans` (\a scans): the registering model, the reports and the fits' settings. */
void
addFromScansOptions (CLI::App* command, BuildModelOptions& options, CLI::Option* scans)
{
  command->add_option ("--model", options.registration.model, "with --from-scans: the model that registers the scans")
      ->needs (scans);
  command
      ->add_option ("--report-dir", options.report_dir,
                    "with --from-scans: folder of each scan's report <id>.json, fit <id>_fit.ply, resampled mesh "
                    "<id>.ply and summary.json (default: the --out path + _scans)")
      ->needs (scans);
  command
      ->add_option ("--fit-components", options.registration.components,
                    "with --from-scans: shape components per region the registration fits (register's --components)")
      ->check (nonNegative ())
      ->needs (scans)
      ->capture_default_str ();
  command
      ->add_option ("--fit-refinement-prior", options.registration.refinement_prior,
                    "with --from-scans: the shape prior of the registration's refinement over all --fit-components "
                    "(register's --refinement-prior)")
      ->check (nonNegative ())
      ->needs (scans)
      ->default_str ((std::ostringstream () << *options.registration.refinement_prior).str ());
  command
      ->add_option ("--fit-refinement-smoothness", options.registration.refinement_smoothness,
                    "with --from-scans: lambda_1 of that refinement (register's --refinement-smoothness)")
      ->check (nonNegative ())
      ->needs (scans)
      ->capture_default_str ();
  command->add_option ("--units", options.registration.units, "with --from-scans: the scans' unit")
      ->check (CLI::IsMember ({"auto", "mm", "cm", "m", "in"}))
      ->needs (scans)
      ->capture_default_str ();
}

void
registerBuildModelCommand (CLI::App& app)
{
  auto options = std::make_shared<BuildModelOptions> ();
  CLI::App* command =
      app.add_subcommand ("build-model", "build a (multi-region) PCA model from meshes in correspondence");
  auto* meshes =
      command->add_option ("--mesh", options->meshes, "mesh file (.ply .obj .vtk .stl .gltf .glb), repeatable");
  auto* directory = command->add_option ("-d,--dir", options->directory,
                                         "folder of meshes (the heads of its population.json if present)");
  command->add_option (
      "--regions", options->regions,
      "region per vertex, JSON {\"regions\": [names], \"labels\": [...]} (default: one global region)");
  command->add_option ("--landmark-vertices", options->landmark_vertices,
                       "landmark vertices, JSON {\"landmark_vertices\": {\"nose_tip\": 123, ...}}");
  auto* ict = command->add_option ("--from-ict", options->ict_directory,
                                   "build the 7-region model from the ICT-FaceKit folder instead of meshes");
  auto* scans = command->add_option (
      "--from-scans", options->from_scans,
      "build from raw scans: a folder of scans or a manifest CSV (rows scan[,landmarks[,id]]), each registered with "
      "--model and resampled into its topology; scans that fail are reported and left out");
  addFromScansOptions (command, *options, scans);
  addResamplingOptions (command, options->resampling);
  command->add_option ("--samples", options->ict.samples, "heads drawn from the ICT model (with --from-ict)")
      ->check (inRange (2, 100000))
      ->capture_default_str ();
  command->add_option ("--seed", options->ict.seed, "seed of the ICT samples")->capture_default_str ();
  command->add_option ("-o,--out", options->out, "model file to write (HDF5, statismo layout)")->capture_default_str ();
  addModelBuilderOptions (command, options->settings);
  command->add_flag ("-q,--quiet", options->quiet, "no progress output");
  ict->excludes (meshes)->excludes (directory);
  scans->excludes (meshes)->excludes (directory)->excludes (ict);
  command->callback ([options] () {
    if (options->meshes.empty () && options->directory.empty () && options->ict_directory.empty () &&
        options->from_scans.empty ())
      throw CLI::RequiredError ("build-model needs --mesh, --dir, --from-ict or --from-scans");
    if (!options->from_scans.empty () && options->registration.model.empty ())
      throw CLI::RequiredError ("build-model --from-scans needs --model, the model that registers the scans");
    runBuildModel (*options);
  });
}

} // namespace tools
} // namespace morphreg
