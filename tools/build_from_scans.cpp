// SPDX-License-Identifier: BSD-3-Clause
// `morphreg build-model --from-scans`: every raw scan of a study registered with a given model and resampled into its
// topology (as `resample` does), the scans that fail reported and left out, and the model built from the rest.
#include "mesh_annotations.h"
#include "pipeline.h"
#include "progress.h"
#include "provenance.h"

#include <morphreg/common/error.h>
#include <morphreg/io/scan_manifest.h>
#include <morphreg/pipeline/batch_summary.h>
#include <morphreg/model/region_segmentation.h>

#include <cmath>
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

/** Registers and resamples one scan into \a report_dir (<id>.json, <id>_fit.ply, <id>.ply); the resampled mesh goes
 *  to \a mesh when both succeed. Returns the scan's report. */
nlohmann::json
registerAndResample (const BuildModelOptions& options, const ScanEntry& entry, const std::string& report_dir,
                     const MorphableModel::Ptr& model, std::optional<TriangleMesh>& mesh)
{
  RegisterOptions registration = options.registration;
  registration.scan = entry.scan;
  registration.landmarks = entry.landmarks;
  registration.out = (fs::path (report_dir) / (entry.id + "_fit.ply")).string ();
  registration.report = (fs::path (report_dir) / (entry.id + ".json")).string ();
  registration.quiet = true;
  const std::string resampled = (fs::path (report_dir) / (entry.id + ".ply")).string ();
  return registerStudyScan (
      registration, model,
      [&] (const ScanRegistrationOutcome& fit, const TriangleMesh& fitted, nlohmann::json& report) {
        std::optional<ResamplingResult> result =
            resampleFit (options.resampling, entry.scan, resampled, *fit.scan.cloud, fitted, report);
        if (result)
          mesh = std::move (result->mesh);
      },
      {resampled});
}

/** The summary row of one scan: status, why it failed, fit RMS, coverage and holes. */
nlohmann::json
scanRow (const ScanEntry& entry, const nlohmann::json& report, bool included, const std::string& report_dir)
{
  const ScanSummary summary = summaryFromReport (entry.id, entry.scan, report);
  const nlohmann::json resampling = report.value ("resampling", nlohmann::json::object ());
  nlohmann::json row = {{"id", entry.id},
                        {"scan", entry.scan},
                        {"status", included ? "ok" : "failed"},
                        {"included", included},
                        {"reason", summary.reason},
                        {"fit_rms_mm", nullptr},
                        {"coverage", resampling.value ("coverage", nlohmann::json ())},
                        {"hole_count", resampling.value ("hole_count", nlohmann::json ())},
                        {"report", (fs::path (report_dir) / (entry.id + ".json")).string ()}};
  if (std::isfinite (summary.rms))
    row["fit_rms_mm"] = summary.rms;
  if (!included && summary.reason.empty ())
    row["reason"] = resampling.value ("reason", "not resampled");
  return row;
}

/** Registers and resamples every scan; returns the meshes that made it and fills \a rows with every scan's row. */
std::vector<TriangleMesh>
resampleScans (const BuildModelOptions& options, const ScanManifest& scans, const std::string& report_dir,
               const MorphableModel::Ptr& model, nlohmann::json& rows)
{
  std::vector<TriangleMesh> meshes;
  const Progress progress ("registering and resampling scans", static_cast<int> (scans.size ()), options.quiet);
  for (std::size_t k = 0; k < scans.size (); ++k) {
    std::optional<TriangleMesh> mesh;
    const nlohmann::json report = registerAndResample (options, scans[k], report_dir, model, mesh);
    const bool included = mesh.has_value () && report.value ("status", "") == "ok";
    if (included)
      meshes.push_back (std::move (*mesh));
    rows.push_back (scanRow (scans[k], report, included, report_dir));
    if (!included)
      std::cerr << "build-model: left out " << scans[k].scan << ": " << rows.back ()["reason"].get<std::string> ()
                << '\n';
    progress.step (static_cast<int> (k + 1), " " + std::to_string (meshes.size ()) + " ok, " +
                                                 std::to_string (k + 1 - meshes.size ()) + " left out");
  }
  progress.finish ();
  return meshes;
}
} // namespace

MorphableModel::Ptr
buildFromScans (const BuildModelOptions& options, const std::string& report_dir, nlohmann::json& summary)
{
  const ScanManifest scans = loadScanList (options.from_scans);
  const MorphableModel::Ptr registering = loadModelFile (options.registration.model, std::cout);
  nlohmann::json rows = nlohmann::json::array ();
  const std::vector<TriangleMesh> meshes = resampleScans (options, scans, report_dir, registering, rows);
  const std::string counts = std::to_string (meshes.size ()) + " of " + std::to_string (scans.size ()) +
                             " scans registered and resampled, " + std::to_string (scans.size () - meshes.size ()) +
                             " left out";
  writeReport ((fs::path (report_dir) / "summary.json").string (), {{"scans", scans.size ()},
                                                                    {"included", meshes.size ()},
                                                                    {"left_out", scans.size () - meshes.size ()},
                                                                    {"model", options.registration.model},
                                                                    {"rows", rows}});
  if (meshes.size () < 2)
    throw InvalidInputError (options.from_scans + ": " + counts + "; a model needs at least two");
  const Eigen::Index num_vertices = registering->numVertices ();
  const ModelBuilder builder (options.settings);
  MorphableModel::Ptr model;
  if (!options.regions.empty ())
    model = builder.build (meshes, loadRegionLabels (options.regions, num_vertices));
  else
    model = registering->numRegions () > 1 ? builder.build (meshes, strongestRegions (*registering))
                                           : builder.buildGlobal (meshes);
  model->setLandmarks (options.landmark_vertices.empty ()
                           ? registering->landmarks ()
                           : loadLandmarkVertices (options.landmark_vertices, num_vertices));
  if (!registering->profileLine ().empty ())
    model->setProfileLine (registering->profileLine ());
  std::cout << "build-model: " << counts << " (reports in " << report_dir << ")\n";
  summary["source"] = {{"scans", scans.size ()},
                       {"included", meshes.size ()},
                       {"left_out", scans.size () - meshes.size ()},
                       {"registering_model", options.registration.model},
                       {"report_dir", report_dir}};
  return model;
}
} // namespace tools
} // namespace morphreg
