// SPDX-License-Identifier: BSD-3-Clause
#include "mesh_annotations.h"

#include <morphreg/common/error.h>
#include <morphreg/io/json_file.h>

#include <algorithm>

namespace morphreg
{
namespace tools
{
void
saveRegionLabels (const std::string& path, const RegionLabels& regions)
{
  writeJsonFile (path, {{"regions", regions.names}, {"labels", regions.labels}});
}

RegionLabels
loadRegionLabels (const std::string& path, Eigen::Index num_vertices)
{
  const nlohmann::json json = readJsonFile (path);
  RegionLabels regions;
  try {
    regions.labels = json.at ("labels").get<std::vector<int>> ();
    if (json.contains ("regions"))
      regions.names = json.at ("regions").get<std::vector<std::string>> ();
    else if (json.contains ("segments")) // the body segment files of ../shared/data/makehuman_bodies
      regions.names = json.at ("segments").get<std::vector<std::string>> ();
    else if (!regions.labels.empty ())
      for (int k = 0; k <= *std::max_element (regions.labels.begin (), regions.labels.end ()); ++k)
        regions.names.push_back ("region_" + std::to_string (k));
  }
  catch (const nlohmann::json::exception& e) {
    throw FormatError (path + ": expected {\"regions\": [names], \"labels\": [region index per vertex]} (" + e.what () +
                       ")");
  }
  try {
    validateRegionLabels (regions, num_vertices);
  }
  catch (const InvalidInputError& e) {
    throw FormatError (path + ": " + e.what ());
  }
  return regions;
}

void
saveLandmarkVertices (const std::string& path, const LandmarkVertices& landmarks)
{
  writeJsonFile (path, {{"landmark_vertices", landmarks}});
}

LandmarkVertices
loadLandmarkVertices (const std::string& path, Eigen::Index num_vertices)
{
  const nlohmann::json json = readJsonFile (path);
  LandmarkVertices landmarks;
  try {
    landmarks = json.at ("landmark_vertices").get<LandmarkVertices> ();
  }
  catch (const nlohmann::json::exception& e) {
    throw FormatError (path + ": expected {\"landmark_vertices\": {\"id\": vertex index, ...}} (" + e.what () + ")");
  }
  for (const auto& [id, vertex] : landmarks)
    if (vertex < 0 || vertex >= num_vertices)
      throw FormatError (path + ": landmark '" + id + "' has vertex " + std::to_string (vertex) + ", valid are 0.." +
                         std::to_string (num_vertices - 1));
  return landmarks;
}
} // namespace tools
} // namespace morphreg
