// SPDX-License-Identifier: BSD-3-Clause
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
  std::vector<std::string> names; ///< one name per region
  std::vector<int> labels;        ///< one region index per vertex
};

/** \brief Throws InvalidInputError if \a regions does not label \a num_vertices vertices with valid indices, a
 *  name is empty or duplicated, or a region is empty.
 *  \param[in] regions the labels to check
 *  \param[in] num_vertices the mesh's vertex count
 */
void
validateRegionLabels (const RegionLabels& regions, Eigen::Index num_vertices);

/** \brief A region seeded by landmark vertices: vertices within \a radius (mm, geodesic) of any seed join it. */
struct LandmarkGroup
{
  std::string name;          ///< the region's name
  std::vector<int> vertices; ///< the seed vertices
  double radius;             ///< geodesic radius around the seeds, mm
};

/** \brief Assigns each vertex to the group whose seeds are geodesically nearest (edge-graph distance over
 *  \a mesh), if within that group's radius; other vertices form the region \a rest_name (listed last).
 *  Throws InvalidInputError for an invalid mesh, an empty group, a seed out of range, a non-positive radius or
 *  a region left empty.
 *  \param[in] mesh the mesh to segment
 *  \param[in] groups the seeded regions
 *  \param[in] rest_name the name of the region of all other vertices
 *  \return the regions and a label per vertex
 */

RegionLabels
segmentByLandmarkGroups (const TriangleMesh& mesh, const std::vector<LandmarkGroup>& groups,
                         const std::string& rest_name = "skull_neck");

class MorphableModel;

/** \brief The regions of \a model as labels: each vertex in the region where its blending weight is largest;
 *  regions left without a vertex are dropped. A model built from meshes in \a model's topology with these labels
 *  has \a model's regions (build-model --from-scans).
 *  \param[in] model a model with blended regions
 *  \return the region names and a label per vertex
 */
RegionLabels
strongestRegions (const MorphableModel& model);

} // namespace morphreg
