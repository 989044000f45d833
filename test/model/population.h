// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A small synthetic training population (coarse heads, fast to build) shared by the model tests.
#include <morphreg/model/region_segmentation.h>
#include <morphreg/synthetic/head_generator.h>

#include <vector>

namespace morphreg
{
namespace test
{
/** Coarse heads (resolution 20: 2402 vertices) so model tests stay fast. */
inline const synthetic::HeadGenerator&
coarseGenerator ()
{
  static const synthetic::HeadGenerator generator (20);
  return generator;
}

/** \a count heads of the population, deterministic. */
inline std::vector<TriangleMesh>
trainingMeshes (int count, std::uint64_t seed = 7)
{
  std::vector<TriangleMesh> meshes;
  for (const auto& head : coarseGenerator ().population (count, seed))
    meshes.push_back (head.mesh);
  return meshes;
}

/** The generator's seven region labels as RegionLabels. */
inline RegionLabels
headRegions ()
{
  return coarseGenerator ().regions ();
}
} // namespace test
} // namespace morphreg
