// SPDX-License-Identifier: BSD-3-Clause
// `morphreg build-model --from-scans`: the library's ModelFromScans with each scan's step writing its outputs as
// `register` and `resample` do (the fit, the report and the resampled mesh) and the study's summary.json.
#include "build_model_console.h"
#include "pipeline.h"
#include "provenance.h"

#include <morphreg/io/scan_manifest.h>
#include <morphreg/pipeline/fit_resampling.h>
#include <morphreg/pipeline/model_building.h>

#include <filesystem>
#include <iostream>
#include <optional>

namespace morphreg
{
namespace tools
{
namespace
{
namespace fs = std::filesystem;

/** Registers and resamples one scan into \a report_dir (<id>.json, <id>_fit.ply, <id>.ply). */
ScanForModel
registerAndResample (const BuildModelOptions& options, const ScanEntry& entry, const std::string& report_dir,
                     const MorphableModel::Ptr& model)
{
  RegisterOptions registration = options.registration;
  registration.scan = entry.scan;
  registration.landmarks = entry.landmarks;
  registration.out = (fs::path (report_dir) / (entry.id + "_fit.ply")).string ();
  registration.report = (fs::path (report_dir) / (entry.id + ".json")).string ();
  registration.quiet = true;
  const std::string resampled = (fs::path (report_dir) / (entry.id + ".ply")).string ();
  ScanForModel done;
  done.report =
      registerStudyScan (registration, model,
                         [&] (const ScanRegistrationOutcome& fit, const TriangleMesh& fitted, nlohmann::json& report) {
                           std::optional<ResamplingResult> result =
                               writeResampledFit (*fit.scan.cloud, entry.scan, fitted, options.resampling,
                                                  {resampled, options.resampling.colours}, report, std::cerr);
                           if (result)
                             done.mesh = std::move (result->mesh);
                         },
                         {resampled});
  return done;
}

/** The console's observer, which also writes the study's summary.json once every scan has been tried. */
class StudySummary : public BuildModelConsole
{
public:
  StudySummary (const BuildModelOptions& options, std::string report_dir)
    : BuildModelConsole (options.quiet), options_ (options), report_dir_ (std::move (report_dir))
  {}

  void
  inputsTried (const std::vector<ModelInput>& inputs) override
  {
    nlohmann::json rows = nlohmann::json::array ();
    std::size_t included = 0;
    for (const ModelInput& input : inputs) {
      rows.push_back (input.row ());
      rows.back ()["report"] = (fs::path (report_dir_) / (input.id + ".json")).string ();
      included += input.included ? 1 : 0;
    }
    writeReport ((fs::path (report_dir_) / "summary.json").string (), {{"scans", inputs.size ()},
                                                                       {"included", included},
                                                                       {"left_out", inputs.size () - included},
                                                                       {"model", options_.registration.model},
                                                                       {"rows", rows}});
  }

private:
  const BuildModelOptions& options_;
  std::string report_dir_;
};
} // namespace

ModelBuildingOutcome
buildFromScans (const BuildModelOptions& options, const std::string& report_dir)
{
  const ScanManifest scans = loadScanList (options.from_scans);
  const MorphableModel::Ptr registering = loadModelFile (options.registration.model, std::cout);
  ModelFromScansSettings settings;
  settings.builder = options.settings;
  settings.regions = options.regions;
  settings.landmark_vertices = options.landmark_vertices;
  settings.registration = options.registration;
  settings.resampling = options.resampling;
  ModelFromScans building (registering, settings);
  building.setScanStep (
      [&] (const ScanEntry& entry) { return registerAndResample (options, entry, report_dir, registering); });
  StudySummary observer (options, report_dir);
  building.setObserver (&observer);
  ModelBuildingOutcome outcome = building.build (scans, options.from_scans);
  const std::size_t included = outcome.source["included"];
  std::cout << "build-model: " << included << " of " << scans.size () << " scans registered and resampled, "
            << scans.size () - included << " left out (reports in " << report_dir << ")\n";
  outcome.source["registering_model"] = options.registration.model;
  outcome.source["report_dir"] = report_dir;
  return outcome;
}
} // namespace tools
} // namespace morphreg
