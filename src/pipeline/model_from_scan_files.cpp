// SPDX-License-Identifier: BSD-3-Clause
// ModelFromScans writing every scan's outputs into a folder (writeScanFilesInto), as build-model --from-scans does.
#include <morphreg/io/json_file.h>
#include <morphreg/pipeline/fit_resampling.h>
#include <morphreg/pipeline/model_building.h>
#include <morphreg/pipeline/scan_file_registration.h>

#include <filesystem>
#include <sstream>

namespace morphreg
{
namespace
{
/** The file \a suffix of scan \a id in \a folder. */
std::string
scanFile (const std::string& folder, const std::string& id, const std::string& suffix)
{
  return (std::filesystem::path (folder) / (id + suffix)).string ();
}
} // namespace

void
ModelFromScans::writeScanFilesInto (const std::string& folder, const std::string& model_file,
                                    const std::string& colours, const nlohmann::json& report_fields)
{
  folder_ = folder;
  model_file_ = model_file;
  summary_fields_ = report_fields;
  step_ = [this, model_file, colours, report_fields] (const ScanEntry& entry) {
    return writeScanFiles (entry, model_file, colours, report_fields);
  };
}

std::vector<std::pair<std::string, std::string>>
ModelFromScans::scanFolderOutputs (const ScanManifest& scans, const std::string& folder)
{
  std::vector<std::pair<std::string, std::string>> outputs;
  for (const ScanEntry& entry : scans) {
    outputs.emplace_back (scanFile (folder, entry.id, ".json"), "the report of scan '" + entry.id + "'");
    outputs.emplace_back (scanFile (folder, entry.id, "_fit.ply"), "the fit of scan '" + entry.id + "'");
    outputs.emplace_back (scanFile (folder, entry.id, ".ply"), "the resampled mesh of scan '" + entry.id + "'");
  }
  outputs.emplace_back (scanFile (folder, "summary", ".json"), "the summary of the scans");
  return outputs;
}

ScanForModel
ModelFromScans::writeScanFiles (const ScanEntry& entry, const std::string& model_file, const std::string& colours,
                                const nlohmann::json& report_fields) const
{
  ScanFileSettings settings;
  static_cast<RegistrationSettings&> (settings) = settings_.registration;
  settings.colours = colours;
  ScanFileRegistration registration (registering_, settings);
  registration.setReportFields (report_fields);
  const std::string resampled = scanFile (folder_, entry.id, ".ply");
  ScanForModel done;
  std::ostringstream warnings;
  const ScanFiles files{entry.scan, entry.landmarks, model_file, scanFile (folder_, entry.id, "_fit.ply"),
                        scanFile (folder_, entry.id, ".json")};
  done.report = registration.registerStudyScan (
      files,
      [&] (const ScanRegistrationOutcome& fit, const TriangleMesh& fitted, nlohmann::json& report) {
        std::optional<ResamplingResult> result = writeResampledFit (
            *fit.scan.cloud, entry.scan, fitted, settings_.resampling, {resampled, "state"}, report, warnings);
        if (result)
          done.mesh = std::move (result->mesh);
      },
      {resampled});
  if (observer_ && !warnings.str ().empty ())
    observer_->warning (entry.id + ": " + warnings.str ());
  return done;
}

void
ModelFromScans::writeSummary (const std::vector<ModelInput>& inputs) const
{
  nlohmann::json rows = nlohmann::json::array ();
  std::size_t included = 0;
  for (const ModelInput& input : inputs) {
    rows.push_back (input.row ());
    rows.back ()["report"] = scanFile (folder_, input.id, ".json");
    included += input.included ? 1 : 0;
  }
  nlohmann::json summary = {{"model", model_file_},
                            {"scans", inputs.size ()},
                            {"included", included},
                            {"left_out", inputs.size () - included},
                            {"rows", rows}};
  summary.update (summary_fields_);
  writeJsonFile (scanFile (folder_, "summary", ".json"), summary);
}
} // namespace morphreg
