#pragma once
/** \file region_segmentation.h
 *  \brief Region labels of a mesh (one region per vertex) and their construction from landmark groups, for
 *  models that come without region labels.
 */
#include <morphreg/mesh/triangle_mesh.h>

#include <string>
#include <vector>

namespace morphreg
{
/** \brief A partition of a mesh's vertices into named regions: labels[v] indexes names. */
struct RegionLabels
{
  std::vector<std::string> names;
  std::vector<int> labels;
};

/** \brief Throws InvalidInputError if \a regions does not label \a num_vertices vertices with valid indices, a
 *  name is empty or duplicated, or a region is empty.
 */
void
validateRegionLabels (const RegionLabels& regions, Eigen::Index num_vertices);

/** \brief A region seeded by landmark vertices: vertices within \a radius (mm, geodesic) of any seed join it. */
struct LandmarkGroup
{
  std::string name;
  std::vector<int> vertices;
  double radius;
};

/** \brief Assigns each vertex to the group whose seeds are geodesically nearest (edge-graph distance over
 *  \a mesh), if within that group's radius; other vertices form the region \a rest_name (listed last).
 *  Throws InvalidInputError for an invalid mesh, an empty group, a seed out of range, a non-positive radius or
 *  a region left empty.
 */
RegionLabels
segmentByLandmarkGroups (const TriangleMesh& mesh, const std::vector<LandmarkGroup>& groups,
                         const std::string& rest_name = "skull_neck");

} // namespace morphreg
