// SPDX-License-Identifier: BSD-3-Clause
#include "scan_resampling.h"

#include "table_options.h"
#include <morphreg/pipeline/scan_colours.h>

#include <morphreg/common/colour_map.h>
#include <morphreg/common/error.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/pipeline/fit_resampling.h>

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
} // namespace

void
addResamplingOptions (CLI::App* command, ResamplingOptions& options)
{
  for (const ResamplingOption& option : resamplingOptions ())
    addTableOption<ResamplingSettings> (command, options, option);
}

std::optional<ResamplingResult>
resampleFit (const ResamplingOptions& options, const std::string& scan_file, const std::string& out,
             const pcl::PointCloud<pcl::PointNormal>& scan, const TriangleMesh& fitted, nlohmann::json& report)
{
  FitResampling resampled =
      morphreg::resampleFit (scan, scan_file, fitted, report["checks"]["passed"].get<bool> (), options);
  report["resampling"] = resampled.report;
  report["resampled_mesh"] = nullptr;
  if (!resampled.result)
    return std::nullopt;
  const ResamplingResult& result = *resampled.result;
  const auto scan_colours = scanColoursAt (scan_file, report["scan"].value ("scale_to_mm", 1.0), options.colours,
                                           result.mesh.vertices, std::cerr);
  savePolygonMesh (out, toPolygonMesh (result.mesh, scan_colours ? *scan_colours : stateColours (result.state)));
  report["resampled_mesh_colours"] = scan_colours ? "scan" : "state";
  report["resampled_mesh"] = out;
  return resampled.result;
}
} // namespace tools
} // namespace morphreg
