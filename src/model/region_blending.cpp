// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/model/region_blending.h>

#include <algorithm>

namespace morphreg
{
std::vector<BlendedRegion>
blendRegions (const MeshTopology& topology, const RegionLabels& regions, int blend_rings)
{
  validateRegionLabels (regions, topology.numVertices ());
  const int grow = std::max (blend_rings, 1);
  const auto num_regions = static_cast<int> (regions.names.size ());
  const Eigen::Index n = topology.numVertices ();

  std::vector<std::vector<int>> rings (num_regions);
  Eigen::VectorXd weight_sum = Eigen::VectorXd::Zero (n);
  for (int j = 0; j < num_regions; ++j) {
    std::vector<int> seeds;
    for (Eigen::Index v = 0; v < n; ++v)
      if (regions.labels[v] == j)
        seeds.push_back (static_cast<int> (v));
    rings[j] = topology.ringIndex (seeds, grow);
    for (Eigen::Index v = 0; v < n; ++v)
      if (rings[j][v] >= 0 && rings[j][v] <= blend_rings)
        weight_sum[v] += 1.0 / (rings[j][v] + 1.0);
  }

  std::vector<BlendedRegion> blended (num_regions);
  for (int j = 0; j < num_regions; ++j) {
    std::vector<double> weights;
    for (Eigen::Index v = 0; v < n; ++v) {
      const int ring = rings[j][v];
      if (ring < 0)
        continue;
      blended[j].vertices.push_back (static_cast<int> (v));
      weights.push_back (ring <= blend_rings ? 1.0 / (ring + 1.0) / weight_sum[v] : 0.0);
    }
    blended[j].weights =
        Eigen::Map<const Eigen::VectorXd> (weights.data (), static_cast<Eigen::Index> (weights.size ()));
  }
  return blended;
}

} // namespace morphreg
