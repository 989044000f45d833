// SPDX-License-Identifier: BSD-3-Clause
// `morphreg evaluate-model`: a model's compactness, generalisation (on held-out meshes) and specificity (against its
// training meshes), per number of components, as text or JSON.
#include "option_checks.h"
#include "commands.h"
#include "pipeline.h"
#include "progress.h"
#include "provenance.h"

#include <morphreg/common/error.h>
#include <morphreg/io/mesh_folder.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/model/model_quality.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace morphreg
{
namespace tools
{
namespace
{
struct EvaluateModelOptions
{
  std::string model;
  std::vector<std::string> meshes;   ///< held-out meshes: folders or files
  std::vector<std::string> training; ///< the model's training meshes: folders or files
  int samples = 1000;
  std::uint64_t seed = 1;
  std::vector<int> components; ///< empty: 1, 2, 5, 10, 20, 50, ... up to the model's count, and the count
  bool json = false;
  bool quiet = false;
};

/** The meshes of folders (as build-model reads them) and files, loaded. */
std::vector<TriangleMesh>
loadMeshList (const std::vector<std::string>& paths, const std::string& what, bool quiet)
{
  std::vector<std::string> files;
  for (const std::string& path : paths) {
    const std::vector<std::string> listed =
        std::filesystem::is_directory (path) ? readMeshFolder (path).files : std::vector<std::string>{path};
    files.insert (files.end (), listed.begin (), listed.end ());
  }
  std::vector<TriangleMesh> meshes;
  if (files.empty ())
    return meshes;
  const Progress progress ("loading " + what, static_cast<int> (files.size ()), quiet);
  for (const std::string& file : files) {
    meshes.push_back (loadTriangleMesh (file));
    progress.step (static_cast<int> (meshes.size ()));
  }
  progress.finish ();
  return meshes;
}

std::vector<int>
componentCounts (const EvaluateModelOptions& options, int available)
{
  std::vector<int> counts = options.components;
  if (counts.empty ()) {
    for (int decade = 1; decade < available; decade *= 10)
      for (const int step : {1, 2, 5})
        if (step * decade < available)
          counts.push_back (step * decade);
    counts.push_back (available);
  }
  for (const int k : counts)
    if (k < 0 || k > available)
      throw InvalidInputError ("evaluate-model: --components " + std::to_string (k) + ": " + options.model + " has " +
                               std::to_string (available) + " global components");
  return counts;
}

nlohmann::json
measureJson (const QualityMeasure& measure)
{
  return {{"mean_mm", measure.mean}, {"std_dev_mm", measure.std_dev}};
}

/** Every measure per component count. */
nlohmann::json
evaluate (const EvaluateModelOptions& options, const MorphableModel& model)
{
  const std::vector<TriangleMesh> held_out = loadMeshList (options.meshes, "held-out meshes", options.quiet);
  const std::vector<TriangleMesh> training = loadMeshList (options.training, "training meshes", options.quiet);
  const Eigen::VectorXd share = compactness (model);
  const std::vector<int> counts = componentCounts (options, static_cast<int> (share.size ()));
  nlohmann::json rows = nlohmann::json::array ();
  const Progress progress ("evaluating", static_cast<int> (counts.size ()), options.quiet);
  for (const int k : counts) {
    nlohmann::json row = {{"components", k},
                          {"compactness", k == 0 ? 0.0 : share[k - 1]},
                          {"generalisation", measureJson (generalisation (model, held_out, k))},
                          {"specificity", nullptr}};
    if (!training.empty ())
      row["specificity"] = measureJson (specificity (model, training, k, options.samples, options.seed));
    rows.push_back (row);
    progress.step (static_cast<int> (rows.size ()));
  }
  progress.finish ();
  return {{"model", options.model},
          {"global_components", share.size ()},
          {"compactness", std::vector<double> (share.data (), share.data () + share.size ())},
          {"held_out_meshes", held_out.size ()},
          {"training_meshes", training.size ()},
          {"samples", options.samples},
          {"seed", options.seed},
          {"distance", "mean vertex distance in correspondence after rigid alignment to the model's mean (mm)"},
          {"measures", rows}};
}

void
printTable (const nlohmann::json& result)
{
  std::cout << result["model"].get<std::string> () << ": " << result["global_components"] << " global components; "
            << result["held_out_meshes"] << " held-out meshes, " << result["training_meshes"] << " training meshes, "
            << result["samples"] << " samples (seed " << result["seed"] << ")\n"
            << "components  compactness  generalisation mm (sd)  specificity mm (sd)\n"
            << std::fixed;
  for (const nlohmann::json& row : result["measures"]) {
    const auto cell = [] (const nlohmann::json& measure) {
      std::ostringstream text;
      if (measure.is_null ())
        text << "- (no --training)";
      else
        text << std::fixed << std::setprecision (3) << measure["mean_mm"].get<double> () << " ("
             << measure["std_dev_mm"].get<double> () << ")";
      return text.str ();
    };
    std::cout << std::setw (10) << row["components"].get<int> () << "  " << std::setw (11) << std::setprecision (4)
              << row["compactness"].get<double> () << "  " << std::setw (22) << cell (row["generalisation"]) << "  "
              << cell (row["specificity"]) << '\n';
  }
}
} // namespace

void
registerEvaluateModelCommand (CLI::App& app)
{
  auto options = std::make_shared<EvaluateModelOptions> ();
  CLI::App* command = app.add_subcommand (
      "evaluate-model",
      "a model's compactness, generalisation and specificity (Styner et al. 2003) per component count");
  command->add_option ("-m,--model", options->model, "model file (.h5)")->required ();
  command
      ->add_option ("--meshes", options->meshes,
                    "held-out meshes in the model's topology (not in its training set): folders or files")
      ->required ();
  command->add_option ("--training", options->training,
                       "the model's training meshes, folders or files (for specificity; without it none)");
  command->add_option ("--samples", options->samples, "random model shapes for specificity")
      ->check (inRange (1, 10000000))
      ->capture_default_str ();
  command->add_option ("--seed", options->seed, "seed of the random shapes")->capture_default_str ();
  command
      ->add_option ("--components", options->components,
                    "component counts to measure, e.g. 1,5,20 (default: 1, 2, 5, 10, 20, ... and all)")
      ->delimiter (',');
  command->add_flag ("--json", options->json, "print the measures as JSON");
  command->add_flag ("-q,--quiet", options->quiet, "no progress output");
  command->footer ("Distances are mean vertex distances in correspondence (mm), each mesh moved rigidly onto the "
                   "model's mean first; the measures use the model's global PCA (its statismo part).");
  command->callback ([options] () {
    const MorphableModel::Ptr model = loadModelFile (options->model, std::cerr);
    const nlohmann::json result = evaluate (*options, *model);
    if (options->json)
      std::cout << stamped (result).dump (2) << '\n';
    else
      printTable (result);
  });
}
} // namespace tools
} // namespace morphreg
