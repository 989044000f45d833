// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file model_evaluation.h
 *  \brief A shape model's quality the way `morphreg evaluate-model` measures it, for every front end: held-out and
 *  training meshes read from folders or files, then compactness, generalisation and specificity
 *  (morphreg/model/model_quality.h) per number of global components, as one JSON document.
 *
 *  \code
 *  morphreg::ModelEvaluationSettings settings;
 *  settings.components = {1, 5, 20};
 *  const nlohmann::json result =
 *      morphreg::evaluateModel (*morphreg::loadModel ("model.h5"), "model.h5", {"held_out/"}, {"training/"}, settings);
 *  result["measures"][0]["generalisation"]["mean_mm"];
 *  \endcode
 */
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/model/morphable_model.h>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief Settings of evaluateModel(). */
struct ModelEvaluationSettings
{
  int samples = 1000;          ///< random model shapes for specificity
  std::uint64_t seed = 1;      ///< the random shapes' seed
  std::vector<int> components; ///< counts to measure; empty: 1, 2, 5, 10, 20, 50, ... below the model's, and its
};

/** \brief What a model evaluation tells as it goes; every method does nothing by default. */
class ModelEvaluationObserver
{
public:
  virtual ~ModelEvaluationObserver () = default;

  /** A stage over \a count steps starts ("loading held-out meshes", "loading training meshes", "evaluating"). */
  virtual void
  stageStarted (const std::string& /*stage*/, int /*count*/)
  {}

  /** Step \a done (from 1) of the stage is finished. */
  virtual void
  stepDone (int /*done*/)
  {}

  /** The stage ended. */
  virtual void
  stageFinished ()
  {}
};

/** \brief The component counts an evaluation measures: \a requested, or, when it is empty, 1, 2, 5, 10, 20, 50, ...
 *  below \a available and \a available itself. Throws InvalidInputError naming \a model for a count outside
 *  [0, \a available].
 *  \param[in] requested the counts asked for, or none
 *  \param[in] available the model's number of global components
 *  \param[in] model the model's name, for the message
 *  \return the counts, in the order measured
 */
std::vector<int>
evaluationComponentCounts (const std::vector<int>& requested, int available, const std::string& model);

/** \brief The meshes of folders (readMeshFolder(): a population's heads, else every mesh file) and of files, in
 *  order, each checked against the model's vertex count. Throws InvalidInputError naming a mesh of another
 *  topology, and the readers' errors naming the file or folder.
 *  \param[in] paths folders or mesh files
 *  \param[in] model the model the meshes must be in correspondence with
 *  \param[in] stage the stage's name for \a observer ("loading held-out meshes")
 *  \param[in] observer told of each mesh read, or null
 *  \return the meshes
 */
std::vector<TriangleMesh>
loadEvaluationMeshes (const std::vector<std::string>& paths, const MorphableModel& model, const std::string& stage,
                      ModelEvaluationObserver* observer = nullptr);

/** \brief Evaluates \a model: compactness of every global component, then per component count the generalisation
 *  to the held-out meshes and, with training meshes, the specificity. JSON: "model", "global_components",
 *  "compactness" (per component, cumulative), "held_out_meshes", "training_meshes", "samples", "seed", "distance"
 *  (what the distances are) and "measures", one row per count: "components", "compactness", "generalisation" and
 *  "specificity" ({"mean_mm", "std_dev_mm"}; specificity null without training meshes). Throws InvalidInputError
 *  for no held-out mesh (naming \a model_name), a bad count or sample number, and loadEvaluationMeshes()' errors.
 *  \param[in] model the model
 *  \param[in] model_name its name (file) for the result and the messages
 *  \param[in] held_out folders or files of meshes not in the model's training set
 *  \param[in] training folders or files of the model's training meshes, or none (no specificity)
 *  \param[in] settings samples, seed and component counts
 *  \param[in] observer told of the stages, or null
 *  \return the measures as JSON
 */
nlohmann::json
evaluateModel (const MorphableModel& model, const std::string& model_name, const std::vector<std::string>& held_out,
               const std::vector<std::string>& training, const ModelEvaluationSettings& settings,
               ModelEvaluationObserver* observer = nullptr);
} // namespace morphreg
