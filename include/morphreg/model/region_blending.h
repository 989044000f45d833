// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file region_blending.h
 *  \brief Overlapping, blended regions grown from a vertex partition (thesis section 3.4).
 */
#include <morphreg/mesh/mesh_topology.h>
#include <morphreg/model/region_segmentation.h>

#include <vector>

namespace morphreg
{
/** \brief One grown region: its vertices (increasing) and their normalised blending weights. */
struct BlendedRegion
{
  std::vector<int> vertices; ///< the grown region's vertex indices, increasing
  Eigen::VectorXd weights;   ///< the blending weight of each of them
};

/** \brief Grows each labelled region by max(blend_rings, 1) rings over \a topology. A vertex in ring k gets raw
 *  weight 1 / (k + 1) for k <= blend_rings and 0 beyond (so with blend_rings = 0 the regions are hard but still
 *  overlap by one ring, which the smoothness prior needs); weights are normalised to sum to 1 per vertex.
 *  \param[in] topology the mesh's connectivity
 *  \param[in] regions a region label per vertex
 *  \param[in] blend_rings the width of the blending band in rings
 *  \return one grown region per label, in label order
 */

std::vector<BlendedRegion>
blendRegions (const MeshTopology& topology, const RegionLabels& regions, int blend_rings);

} // namespace morphreg
