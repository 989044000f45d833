// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/resampling/resampling_report.h>

#include <nlohmann/json.hpp>

namespace morphreg
{
nlohmann::json
toJson (const ResamplingStatistics& statistics)
{
  nlohmann::json holes = nlohmann::json::array ();
  for (const ResamplingHole& hole : statistics.holes)
    holes.push_back ({{"vertices", hole.vertices},
                      {"area_mm2", hole.area},
                      {"ring_vertices", hole.ring_vertices},
                      {"max_fill_mm", hole.max_fill},
                      {"folded_triangles", hole.folded_triangles}});
  return {{"vertices", statistics.vertices},
          {"observed", statistics.observed},
          {"filled", statistics.filled},
          {"coverage", statistics.coverage},
          {"observed_area_fraction", statistics.observed_area},
          {"largest_hole_area_fraction", statistics.largest_hole_area},
          {"folded_triangles", statistics.folded_triangles},
          {"median_displacement_mm", statistics.median_displacement},
          {"hole_count", statistics.holes.size ()},
          {"holes", holes},
          {"timings_s", {{"rays", statistics.ray_seconds}, {"fill", statistics.fill_seconds}}}};
}

} // namespace morphreg
