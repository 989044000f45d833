// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Shared by the samples that run without any files: the built-in synthetic head population, a small multi-region
// model built from it, and a simulated laser scan of a head that is not in that population.
#include <morphreg/model/model_builder.h>
#include <morphreg/synthetic/head_generator.h>
#include <morphreg/synthetic/scan_simulator.h>

#include <vector>

namespace samples
{
namespace synthetic = morphreg::synthetic;

/** Heads seed, seed + 1, ..., seed + count - 1 of the population, as meshes in one topology (mm). */
inline std::vector<morphreg::TriangleMesh>
populationMeshes (const synthetic::HeadGenerator& generator, int count, std::uint64_t seed)
{
  std::vector<morphreg::TriangleMesh> meshes;
  for (auto& head : generator.population (count, seed))
    meshes.push_back (std::move (head.mesh));
  return meshes;
}

/** A seven-region model of \a count heads with at most \a components components per region, with landmarks and the
 *  profile line.
 */
inline morphreg::MorphableModel::Ptr
buildHeadModel (const synthetic::HeadGenerator& generator, int count, int components)
{
  morphreg::ModelBuilderSettings settings;
  settings.max_components = components;
  auto model = morphreg::ModelBuilder (settings).build (populationMeshes (generator, count, 1), generator.regions ());
  model->setLandmarks (generator.landmarks ());
  model->setProfileLine (generator.profileLine ());
  return model;
}

/** A head drawn after the model's \a count heads (so not in the model) and a laser scan of it in a random pose. */
struct UnseenScan
{
  synthetic::SyntheticHead head;
  synthetic::SimulatedScan scan;
  Eigen::Matrix3Xd truth; ///< the head's vertices posed into the scan frame: the answer a fit should find
};

inline UnseenScan
scanUnseenHead (const synthetic::HeadGenerator& generator, int count,
                const synthetic::ScanSimulator::Parameters& scanner = {})
{
  UnseenScan unseen;
  unseen.head = generator.sample (1 + static_cast<std::uint64_t> (count));
  unseen.scan = synthetic::ScanSimulator (scanner).scan (unseen.head.mesh, 7);
  unseen.truth = unseen.scan.head_to_scan * unseen.head.mesh.vertices;
  return unseen;
}
} // namespace samples
