// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// One shared head generator per resolution for a test executable (building one takes a moment), and a model of
// its heads.
#include <morphreg/model/model_builder.h>
#include <morphreg/synthetic/head_generator.h>

#include <cstdint>
#include <map>
#include <memory>
#include <vector>

namespace morphreg
{
namespace test
{
inline const synthetic::HeadGenerator&
headGenerator (int resolution = 40)
{
  static std::map<int, std::unique_ptr<synthetic::HeadGenerator>> generators;
  auto& generator = generators[resolution];
  if (!generator)
    generator = std::make_unique<synthetic::HeadGenerator> (resolution);
  return *generator;
}

/** A model of \a heads heads of the default generator (population seed \a seed), its regions and landmarks, with
 *  at most \a components components per region. */
inline MorphableModel::Ptr
headModel (int heads, int components, std::uint64_t seed = 1000)
{
  const auto& generator = headGenerator ();
  std::vector<TriangleMesh> meshes;
  for (auto& head : generator.population (heads, seed))
    meshes.push_back (std::move (head.mesh));
  ModelBuilderSettings settings;
  settings.max_components = components;
  MorphableModel::Ptr model = ModelBuilder (settings).build (meshes, generator.regions ());
  model->setLandmarks (generator.landmarks ());
  return model;
}
} // namespace test
} // namespace morphreg
