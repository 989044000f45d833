// SPDX-License-Identifier: BSD-3-Clause
#include "scan_resampling.h"

#include "option_checks.h"
#include "scan_colours.h"

#include <morphreg/common/colour_map.h>
#include <morphreg/common/error.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>

#include <chrono>
#include <iostream>

namespace morphreg
{
namespace tools
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

nlohmann::json
statisticsJson (const ResamplingStatistics& stats)
{
  nlohmann::json holes = nlohmann::json::array ();
  for (const ResamplingHole& hole : stats.holes)
    holes.push_back ({{"vertices", hole.vertices},
                      {"area_mm2", hole.area},
                      {"ring_vertices", hole.ring_vertices},
                      {"max_fill_mm", hole.max_fill},
                      {"folded_triangles", hole.folded_triangles}});
  return {{"vertices", stats.vertices},
          {"observed", stats.observed},
          {"filled", stats.filled},
          {"coverage", stats.coverage},
          {"observed_area_fraction", stats.observed_area},
          {"largest_hole_area_fraction", stats.largest_hole_area},
          {"folded_triangles", stats.folded_triangles},
          {"median_displacement_mm", stats.median_displacement},
          {"hole_count", stats.holes.size ()},
          {"holes", holes},
          {"timings_s", {{"rays", stats.ray_seconds}, {"fill", stats.fill_seconds}}}};
}
} // namespace

void
addResamplingOptions (CLI::App* command, ResamplingOptions& options)
{
  command
      ->add_option ("--ray-distance", options.ray_distance,
                    "farthest a vertex moves along its normal onto the scan (mm); beyond it the vertex is filled")
      ->check (positive ())
      ->capture_default_str ();
  command
      ->add_option ("--normal-agreement", options.normal_agreement,
                    "largest angle between a vertex normal and the scan's at the hit (degrees)")
      ->check (inRange (1.0, 180.0))
      ->capture_default_str ();
  command->add_option ("--ring-width", options.ring_width, "rings of observed vertices around a hole that fill it")
      ->check (inRange (1, 20))
      ->capture_default_str ();
  command
      ->add_option ("--max-hole-fraction", options.max_hole_fraction,
                    "largest share of the model's surface one hole may cover (else the scan is refused)")
      ->check (inRange (0.01, 1.0))
      ->capture_default_str ();
  command->add_option ("--fill-smoothing", options.fill_smoothing, "thin plate spline smoothing of the fills (mm)")
      ->check (nonNegative ())
      ->capture_default_str ();
  command
      ->add_option ("--passes", options.passes,
                    "resampling passes; each after the first casts again from the previous one's fills")
      ->check (inRange (1, 10))
      ->capture_default_str ();
}

std::optional<ResamplingResult>
resampleFit (const ResamplingOptions& options, const std::string& scan_file, const std::string& out,
             const pcl::PointCloud<pcl::PointNormal>& scan, const TriangleMesh& fitted, nlohmann::json& report)
{
  if (!report["checks"]["passed"].get<bool> ()) {
    report["resampling"] = {{"status", "skipped"}, {"reason", "the fit failed its checks"}};
    report["resampled_mesh"] = nullptr;
    return std::nullopt;
  }
  const auto start = std::chrono::steady_clock::now ();
  ScanResampler resampler;
  resampler.setMaxDistance (options.ray_distance);
  resampler.setNormalAgreement (options.normal_agreement);
  resampler.setRingWidth (options.ring_width);
  resampler.setMaxHoleFraction (options.max_hole_fraction);
  resampler.setFillRegularization (options.fill_smoothing);
  resampler.setPasses (options.passes);
  resampler.setInputReference (fitted);
  ResamplingResult result;
  try {
    resampler.setInputScan (scan);
    result = resampler.resample ();
  }
  catch (const InvalidInputError& e) {
    throw InvalidInputError (scan_file + ": cannot be resampled into the model's topology: " + e.what ());
  }
  const auto scan_colours = scanColoursAt (scan_file, report["scan"].value ("scale_to_mm", 1.0), options.colours,
                                           result.mesh.vertices, std::cerr);
  savePolygonMesh (out, toPolygonMesh (result.mesh, scan_colours ? *scan_colours : stateColours (result.state)));
  report["resampled_mesh_colours"] = scan_colours ? "scan" : "state";
  report["resampling"] = statisticsJson (result.statistics);
  report["resampling"]["status"] = "ok";
  report["resampling"]["settings"] = {
      {"ray_distance_mm", options.ray_distance},  {"normal_agreement_deg", options.normal_agreement},
      {"ring_width", options.ring_width},         {"max_hole_fraction", options.max_hole_fraction},
      {"fill_smoothing", options.fill_smoothing}, {"passes", options.passes}};
  report["resampling"]["timings_s"]["total"] =
      std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
  report["resampled_mesh"] = out;
  return result;
}
} // namespace tools
} // namespace morphreg
