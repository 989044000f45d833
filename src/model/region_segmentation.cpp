// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/mesh/mesh_topology.h>
#include <morphreg/model/morphable_model.h>
#include <morphreg/model/region_segmentation.h>

#include <cmath>
#include <limits>
#include <set>

namespace morphreg
{
void
validateRegionLabels (const RegionLabels& regions, Eigen::Index num_vertices)
{
  if (static_cast<Eigen::Index> (regions.labels.size ()) != num_vertices)
    throw InvalidInputError ("region labels: " + std::to_string (regions.labels.size ()) + " labels for " +
                             std::to_string (num_vertices) + " vertices");
  std::set<std::string> names;
  for (const std::string& name : regions.names)
    if (name.empty () || !names.insert (name).second)
      throw InvalidInputError ("region labels: region name '" + name + "' is empty or duplicated");
  std::vector<int> sizes (regions.names.size (), 0);
  for (size_t v = 0; v < regions.labels.size (); ++v) {
    const int label = regions.labels[v];
    if (label < 0 || label >= static_cast<int> (regions.names.size ()))
      throw InvalidInputError ("region labels: vertex " + std::to_string (v) + " has label " + std::to_string (label) +
                               ", valid are 0.." + std::to_string (regions.names.size () - 1));
    ++sizes[label];
  }
  for (size_t j = 0; j < sizes.size (); ++j)
    if (sizes[j] == 0)
      throw InvalidInputError ("region labels: region '" + regions.names[j] + "' has no vertices");
}

RegionLabels
segmentByLandmarkGroups (const TriangleMesh& mesh, const std::vector<LandmarkGroup>& groups,
                         const std::string& rest_name)
{
  validateMesh (mesh, "segmentByLandmarkGroups mesh");
  const MeshTopology topology (mesh);
  const Eigen::Index n = mesh.numVertices ();
  RegionLabels result;
  result.labels.assign (n, static_cast<int> (groups.size ()));
  std::vector<double> best (n, std::numeric_limits<double>::infinity ());
  for (size_t g = 0; g < groups.size (); ++g) {
    const LandmarkGroup& group = groups[g];
    if (group.vertices.empty () || !(group.radius > 0.0) || !std::isfinite (group.radius))
      throw InvalidInputError ("segmentByLandmarkGroups: group '" + group.name +
                               "' needs seed vertices and a finite positive radius");
    for (const int v : group.vertices)
      if (v < 0 || v >= n)
        throw InvalidInputError ("segmentByLandmarkGroups: group '" + group.name + "' seed " + std::to_string (v) +
                                 " is out of range [0, " + std::to_string (n) + ")");
    const std::vector<double> distance = topology.geodesicDistances (mesh.vertices, group.vertices, group.radius);
    for (Eigen::Index v = 0; v < n; ++v)
      if (distance[v] < best[v]) {
        best[v] = distance[v];
        result.labels[v] = static_cast<int> (g);
      }
    result.names.push_back (group.name);
  }
  result.names.push_back (rest_name);
  validateRegionLabels (result, n);
  return result;
}

RegionLabels
strongestRegions (const MorphableModel& model)
{
  std::vector<int> strongest (static_cast<std::size_t> (model.numVertices ()));
  for (int v = 0; v < model.numVertices (); ++v) {
    double best = -1.0;
    for (const RegionEntry& entry : model.vertexEntries (v))
      if (entry.weight > best) {
        best = entry.weight;
        strongest[static_cast<std::size_t> (v)] = entry.region;
      }
  }
  RegionLabels regions;
  std::vector<int> index (static_cast<std::size_t> (model.numRegions ()), -1);
  for (int& region : strongest) {
    int& label = index[static_cast<std::size_t> (region)];
    if (label < 0) {
      label = static_cast<int> (regions.names.size ());
      regions.names.push_back (model.region (region).name);
    }
    regions.labels.push_back (label);
  }
  return regions;
}

} // namespace morphreg
