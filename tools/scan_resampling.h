// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The resampling step after a registration, shared by `resample` and `build-model --from-scans`: the scan moved into
// the fitted model's topology by ScanResampler, the mesh written and its statistics added to the scan's report.
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/resampling/resampling_settings.h>
#include <morphreg/resampling/scan_resampler.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <nlohmann/json.hpp>

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace morphreg
{
namespace tools
{
/** The ScanResampler settings of the command line (the library's, by the same names) and the mesh's colours. */
struct ResamplingOptions : ResamplingSettings
{
  std::string colours = "state"; ///< the resampled mesh's vertex colours: auto, scan or state (observed / filled)
};

/** Adds the options of resamplingOptions()'s table (--ray-distance, --passes, ...) to \a command. */
void
addResamplingOptions (CLI::App* command, ResamplingOptions& options);

/** Resamples \a scan (file \a scan_file, for messages) into the topology of \a fitted, writes the resampled mesh to
 *  \a out (PLY; vertex colours as options.colours says: the scan's, see scanColoursAt, at report["scan"]
 *  ["scale_to_mm"], or grey observed, orange filled) and adds "resampling", "resampled_mesh" and
 *  "resampled_mesh_colours" to \a report. A fit that failed its checks is not resampled (the report says so):
 *  returns nothing. Throws InvalidInputError naming the scan when the resampler refuses it (no overlap, another
 *  unit, too large a hole).
 */
std::optional<ResamplingResult>
resampleFit (const ResamplingOptions& options, const std::string& scan_file, const std::string& out,
             const pcl::PointCloud<pcl::PointNormal>& scan, const TriangleMesh& fitted, nlohmann::json& report);
} // namespace tools
} // namespace morphreg
