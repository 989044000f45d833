// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/mesh_annotations.h>

#include <algorithm>
#include <limits>

namespace morphreg
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
    regions.labels = jsonWholeNumbers (json.at ("labels"), 0, std::numeric_limits<int>::max (), path + ": labels");
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
  const auto found = json.find ("landmark_vertices");
  if (!json.is_object () || found == json.end () || !found->is_object ())
    throw FormatError (path + ": expected {\"landmark_vertices\": {\"id\": vertex index, ...}}");
  LandmarkVertices landmarks;
  for (const auto& [id, vertex] : found->items ()) {
    try {
      requireKnownLandmarkId (id, path);
    }
    catch (const InvalidInputError& e) {
      throw FormatError (e.what ());
    }
    landmarks[id] = static_cast<int> (
        jsonWholeNumber (vertex, 0, num_vertices - 1, path + ": the vertex of landmark '" + id + "'"));
  }
  return landmarks;
}
} // namespace morphreg
