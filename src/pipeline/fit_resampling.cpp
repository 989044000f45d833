// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/colour_map.h>
#include <morphreg/common/error.h>
#include <morphreg/common/cloud_matrix.h>
#include <morphreg/io/landmark_io.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/pipeline/fit_resampling.h>
#include <morphreg/pipeline/scan_colours.h>
#include <morphreg/pipeline/scan_units.h>
#include <morphreg/registration/scan_checks.h>
#include <morphreg/resampling/landmark_reference.h>
#include <morphreg/resampling/resampling_report.h>

#include <chrono>

namespace morphreg
{
namespace
{
/** Observed vertices light grey, filled ones orange. */
VertexColours
stateColours (const std::vector<ResampledVertex>& state)
{
  VertexColours colours (3, static_cast<Eigen::Index> (state.size ()));
  for (std::size_t v = 0; v < state.size (); ++v)
    colours.col (static_cast<Eigen::Index> (v)) =
        state[v] == ResampledVertex::observed ? Rgb8 (200, 200, 200) : Rgb8 (240, 120, 20);
  return colours;
}
} // namespace

FitResampling
resampleFit (const pcl::PointCloud<pcl::PointNormal>& scan, const std::string& scan_name, const TriangleMesh& fitted,
             bool fit_passed, const ResamplingSettings& settings)
{
  if (!fit_passed)
    return {std::nullopt, {{"status", "skipped"}, {"reason", "the fit failed its checks"}}};
  const auto start = std::chrono::steady_clock::now ();
  ScanResampler resampler;
  resampler.setSettings (settings);
  resampler.setInputReference (fitted);
  FitResampling resampled;
  try {
    resampler.setInputScan (scan);
    resampled.result = resampler.resample ();
  }
  catch (const InvalidInputError& e) {
    throw InvalidInputError (scan_name + ": cannot be resampled into the model's topology: " + e.what ());
  }
  resampled.report = toJson (resampled.result->statistics);
  resampled.report["status"] = "ok";
  resampled.report["settings"] = toJson (settings);
  resampled.report["timings_s"]["total"] =
      std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
  return resampled;
}

std::optional<ResamplingResult>
writeResampledFit (const pcl::PointCloud<pcl::PointNormal>& scan, const std::string& scan_file,
                   const TriangleMesh& fitted, const ResamplingSettings& settings, const ResampledMeshFile& file,
                   nlohmann::json& report, std::ostream& warnings)
{
  FitResampling resampled = resampleFit (scan, scan_file, fitted, report["checks"]["passed"].get<bool> (), settings);
  report["resampling"] = resampled.report;
  report["resampled_mesh"] = nullptr;
  if (!resampled.result)
    return std::nullopt;
  const ResamplingResult& result = *resampled.result;
  const auto scan_colours = scanColoursAt (scan_file, report["scan"].value ("scale_to_mm", 1.0), file.colours,
                                           result.mesh.vertices, warnings);
  savePolygonMesh (file.path, toPolygonMesh (result.mesh, scan_colours ? *scan_colours : stateColours (result.state)));
  report["resampled_mesh_colours"] = scan_colours ? "scan" : "state";
  report["resampled_mesh"] = file.path;
  return std::move (resampled.result);
}

LandmarkResampling
resampleFromLandmarks (const MorphableModel& model, const LandmarkResamplingFiles& files, const std::string& units,
                       const ResamplingSettings& settings, std::ostream& warnings)
{
  if (files.landmarks.empty ())
    throw InvalidInputError ("resampling " + files.scan +
                             " from landmarks: no landmark file (landmarks marked on the "
                             "scan place the reference)");
  const ScanInput as_read = readScanOrDepthImage (files.scan, files.intrinsics, files.resampled.colours, units);
  LandmarkResampling outcome;
  outcome.unit = scanInputUnit (as_read, units, model);
  const ScanInput scan = scaledScan (as_read, outcome.unit.scale_to_mm);
  const LandmarkPositions landmarks = loadLandmarks (files.landmarks);
  requireLandmarksOnScan (landmarks, pointsOf (*scan.cloud), files.landmarks);
  const TriangleMesh reference = landmarkReference (model.meanMesh (), model.landmarks (), landmarks, files.landmarks);
  saveTriangleMesh (files.reference, reference);
  outcome.report = {
      {"status", "ok"},
      {"checks", {{"passed", true}, {"failures", nlohmann::json::array ()}}},
      {"units", "mm"},
      {"scan",
       {{"file", files.scan},
        {"points", scan.cloud->size ()},
        {"units", toString (outcome.unit.unit)},
        {"scale_to_mm", outcome.unit.scale_to_mm}}},
      {"reference", {{"method", "landmarks"}, {"landmarks", files.landmarks}, {"mesh", files.reference}}}};
  outcome.result =
      writeResampledFit (*scan.cloud, files.scan, reference, settings, files.resampled, outcome.report, warnings);
  return outcome;
}

} // namespace morphreg
