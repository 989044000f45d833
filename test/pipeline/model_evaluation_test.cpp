// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/model/model_builder.h>
#include <morphreg/pipeline/model_evaluation.h>

#include "support/expect_error.h"
#include "support/synthetic_heads.h"
#include "support/temp_directory.h"

#include <gtest/gtest.h>

using morphreg::MorphableModel;
using morphreg::TriangleMesh;

namespace
{
/** Five heads written as files into a folder of their own, and the global model built from them. */
struct TinyStudy
{
  morphreg::test::TempDirectory dir;
  std::vector<std::string> files;
  MorphableModel::Ptr model;

  TinyStudy ()
  {
    std::vector<TriangleMesh> meshes;
    for (auto& head : morphreg::test::headGenerator ().population (5, 300)) {
      files.push_back (dir.file ("head_" + std::to_string (files.size ()) + ".ply"));
      morphreg::saveTriangleMesh (files.back (), head.mesh);
      meshes.push_back (std::move (head.mesh));
    }
    model = morphreg::ModelBuilder ().buildGlobal (meshes);
  }
};

const TinyStudy&
study ()
{
  static const TinyStudy instance;
  return instance;
}

/** Records the stages and their steps. */
class StageLog : public morphreg::ModelEvaluationObserver
{
public:
  std::vector<std::string> stages;
  std::vector<int> steps;

  void
  stageStarted (const std::string& stage, int count) override
  {
    stages.push_back (stage + " " + std::to_string (count));
  }

  void
  stepDone (int done) override
  {
    steps.push_back (done);
  }
};
} // namespace

TEST (ModelEvaluationTest, TrainingMeshesReproducedAtAllComponents)
{
  morphreg::ModelEvaluationSettings settings;
  settings.samples = 20;
  StageLog log;
  const nlohmann::json result =
      morphreg::evaluateModel (*study ().model, "tiny.h5", study ().files, study ().files, settings, &log);
  const int all = static_cast<int> (study ().model->globalVariances ().size ());
  ASSERT_EQ (result["global_components"], all);
  EXPECT_EQ (result["held_out_meshes"], 5);
  EXPECT_EQ (result["training_meshes"], 5);
  const nlohmann::json& rows = result["measures"];
  ASSERT_EQ (rows.size (), morphreg::evaluationComponentCounts ({}, all, "tiny.h5").size ());
  for (std::size_t r = 1; r < rows.size (); ++r)
    EXPECT_GE (rows[r]["compactness"].get<double> (), rows[r - 1]["compactness"].get<double> ());
  const nlohmann::json& last = rows.back ();
  EXPECT_EQ (last["components"], all);
  EXPECT_NEAR (last["compactness"].get<double> (), 1.0, 1e-12);
  EXPECT_LT (last["generalisation"]["mean_mm"].get<double> (), 1e-3);
  EXPECT_GT (rows[0]["generalisation"]["mean_mm"].get<double> (), 0.1);
  EXPECT_GT (last["specificity"]["mean_mm"].get<double> (), 0.0);
  EXPECT_EQ (log.stages, (std::vector<std::string>{"loading held-out meshes 5", "loading training meshes 5",
                                                   "evaluating " + std::to_string (rows.size ())}));
  EXPECT_EQ (log.steps.size (), 10 + rows.size ());
}

TEST (ModelEvaluationTest, DefaultCountsAndWithoutTraining)
{
  EXPECT_EQ (morphreg::evaluationComponentCounts ({}, 25, "m"), (std::vector<int>{1, 2, 5, 10, 20, 25}));
  EXPECT_EQ (morphreg::evaluationComponentCounts ({}, 10, "m"), (std::vector<int>{1, 2, 5, 10}));
  EXPECT_EQ (morphreg::evaluationComponentCounts ({0, 3}, 4, "m"), (std::vector<int>{0, 3}));
  morphreg::ModelEvaluationSettings settings;
  settings.components = {0, 1};
  const nlohmann::json result = morphreg::evaluateModel (*study ().model, "tiny.h5", {study ().files[0]}, {}, settings);
  ASSERT_EQ (result["measures"].size (), 2u);
  EXPECT_EQ (result["measures"][0]["compactness"], 0.0);
  EXPECT_TRUE (result["measures"][1]["specificity"].is_null ());
  EXPECT_EQ (result["training_meshes"], 0);
}

TEST (ModelEvaluationTest, BadInputIsNamed)
{
  const MorphableModel& model = *study ().model;
  morphreg::ModelEvaluationSettings settings;
  settings.components = {99};
  morphreg::test::expectErrorContaining<morphreg::InvalidInputError> (
      [&] { morphreg::evaluateModel (model, "tiny.h5", study ().files, {}, settings); }, "tiny.h5: 99 components");
  morphreg::test::expectErrorContaining<morphreg::InvalidInputError> (
      [&] { morphreg::evaluateModel (model, "tiny.h5", {}, {}, {}); }, "tiny.h5: no held-out meshes");
  const std::string other = study ().dir.file ("coarse.ply");
  morphreg::saveTriangleMesh (other, morphreg::test::headGenerator (20).sample (1).mesh);
  morphreg::test::expectErrorContaining<morphreg::InvalidInputError> (
      [&] {
        morphreg::evaluateModel (model, "tiny.h5", {study ().files[0], other}, {}, {});
      },
      other + ": ");
  morphreg::test::expectErrorContaining<morphreg::IoError> (
      [&] { morphreg::evaluateModel (model, "tiny.h5", {study ().dir.file ("missing.ply")}, {}, {}); }, "missing.ply");
}
