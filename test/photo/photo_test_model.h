// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The photo tests' model: 200 synthetic heads (seed 1000) at a low resolution, 20 components per region, with the
// generator's landmarks and profile line; and the thesis's frontal landmarks (table 1) of the generator.
#include "support/synthetic_heads.h"

#include <morphreg/common/landmarks.h>
#include <morphreg/model/model_builder.h>
#include <morphreg/synthetic/head_generator.h>

#include <memory>

namespace morphreg
{
namespace test
{
constexpr int kPhotoResolution = 24;
constexpr int kPhotoTrainingHeads = 200;
constexpr std::uint64_t kPhotoTrainingSeed = 1000;

/** The model, and the mean of its training heads in the generator's frame (the model's frame differs from it by
 *  the rigid Procrustes alignment).
 */
struct PhotoTestModel
{
  MorphableModel::ConstPtr model;
  Eigen::Matrix3Xd training_mean;
};

inline const PhotoTestModel&
photoTestModel ()
{
  static const PhotoTestModel built = [] {
    const synthetic::HeadGenerator& generator = headGenerator (kPhotoResolution);
    std::vector<TriangleMesh> meshes;
    for (auto& head : generator.population (kPhotoTrainingHeads, kPhotoTrainingSeed))
      meshes.push_back (std::move (head.mesh));
    PhotoTestModel result;
    result.training_mean = Eigen::Matrix3Xd::Zero (3, generator.numVertices ());
    for (const TriangleMesh& mesh : meshes)
      result.training_mean += mesh.vertices / static_cast<double> (meshes.size ());
    ModelBuilderSettings settings;
    settings.max_components = 20;
    auto model = ModelBuilder (settings).build (meshes, generator.regions ());
    model->setLandmarks (generator.landmarks ());
    model->setProfileLine (generator.profileLine ());
    result.model = model;
    return result;
  }();
  return built;
}

/** The generator's landmarks among the 40 frontal ones of docs/landmarks.md (thesis table 1). */
inline LandmarkVertices
frontalLandmarks ()
{
  return morphreg::frontalLandmarks (headGenerator (kPhotoResolution).landmarks ());
}
} // namespace test
} // namespace morphreg
