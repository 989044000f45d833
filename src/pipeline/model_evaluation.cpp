// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/mesh_folder.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/model/model_quality.h>
#include <morphreg/pipeline/model_evaluation.h>

#include <filesystem>

namespace morphreg
{
namespace
{
/** The mesh files of folders and files, in order. */
std::vector<std::string>
meshFiles (const std::vector<std::string>& paths)
{
  std::vector<std::string> files;
  for (const std::string& path : paths) {
    const std::vector<std::string> listed =
        std::filesystem::is_directory (path) ? readMeshFolder (path).files : std::vector<std::string>{path};
    files.insert (files.end (), listed.begin (), listed.end ());
  }
  return files;
}

nlohmann::json
measureJson (const QualityMeasure& measure)
{
  return {{"mean_mm", measure.mean}, {"std_dev_mm", measure.std_dev}};
}

/** One row per count: compactness, generalisation and (with training meshes) specificity. */
nlohmann::json
measureRows (const MorphableModel& model, const Eigen::VectorXd& share, const std::vector<int>& counts,
             const std::vector<TriangleMesh>& held_out, const std::vector<TriangleMesh>& training,
             const ModelEvaluationSettings& settings, ModelEvaluationObserver* observer)
{
  nlohmann::json rows = nlohmann::json::array ();
  if (observer)
    observer->stageStarted ("evaluating", static_cast<int> (counts.size ()));
  for (const int k : counts) {
    nlohmann::json row = {{"components", k},
                          {"compactness", k == 0 ? 0.0 : share[k - 1]},
                          {"generalisation", measureJson (generalisation (model, held_out, k))},
                          {"specificity", nullptr}};
    if (!training.empty ())
      row["specificity"] = measureJson (specificity (model, training, k, settings.samples, settings.seed));
    rows.push_back (row);
    if (observer)
      observer->stepDone (static_cast<int> (rows.size ()));
  }
  if (observer)
    observer->stageFinished ();
  return rows;
}
} // namespace

std::vector<int>
evaluationComponentCounts (const std::vector<int>& requested, int available, const std::string& model)
{
  std::vector<int> counts = requested;
  if (counts.empty ()) {
    for (int decade = 1; decade < available; decade *= 10)
      for (const int step : {1, 2, 5})
        if (step * decade < available)
          counts.push_back (step * decade);
    counts.push_back (available);
  }
  for (const int k : counts)
    if (k < 0 || k > available)
      throw InvalidInputError (model + ": " + std::to_string (k) + " components asked for; it has " +
                               std::to_string (available) + " global components");
  return counts;
}

std::vector<TriangleMesh>
loadEvaluationMeshes (const std::vector<std::string>& paths, const MorphableModel& model, const std::string& stage,
                      ModelEvaluationObserver* observer)
{
  const std::vector<std::string> files = meshFiles (paths);
  std::vector<TriangleMesh> meshes;
  if (files.empty ())
    return meshes;
  if (observer)
    observer->stageStarted (stage, static_cast<int> (files.size ()));
  for (const std::string& file : files) {
    meshes.push_back (loadTriangleMesh (file));
    if (meshes.back ().vertices.cols () != model.numVertices ())
      throw InvalidInputError (file + ": " + std::to_string (meshes.back ().vertices.cols ()) +
                               " vertices; the model's topology has " + std::to_string (model.numVertices ()));
    if (observer)
      observer->stepDone (static_cast<int> (meshes.size ()));
  }
  if (observer)
    observer->stageFinished ();
  return meshes;
}

nlohmann::json
evaluateModel (const MorphableModel& model, const std::string& model_name, const std::vector<std::string>& held_out,
               const std::vector<std::string>& training, const ModelEvaluationSettings& settings,
               ModelEvaluationObserver* observer)
{
  if (held_out.empty ())
    throw InvalidInputError (model_name + ": no held-out meshes to measure the generalisation on");
  const Eigen::VectorXd share = compactness (model);
  const std::vector<int> counts =
      evaluationComponentCounts (settings.components, static_cast<int> (share.size ()), model_name);
  const std::vector<TriangleMesh> held_out_meshes =
      loadEvaluationMeshes (held_out, model, "loading held-out meshes", observer);
  const std::vector<TriangleMesh> training_meshes =
      loadEvaluationMeshes (training, model, "loading training meshes", observer);
  return {{"model", model_name},
          {"global_components", share.size ()},
          {"compactness", std::vector<double> (share.data (), share.data () + share.size ())},
          {"held_out_meshes", held_out_meshes.size ()},
          {"training_meshes", training_meshes.size ()},
          {"samples", settings.samples},
          {"seed", settings.seed},
          {"distance", "mean vertex distance in correspondence after rigid alignment to the model's mean (mm)"},
          {"measures", measureRows (model, share, counts, held_out_meshes, training_meshes, settings, observer)}};
}
} // namespace morphreg
