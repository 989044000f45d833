// SPDX-License-Identifier: BSD-3-Clause
// `morphreg evaluate-model`: a model's compactness, generalisation (on held-out meshes) and specificity (against its
// training meshes), per number of components, as text or JSON.
#include "option_checks.h"
#include "commands.h"
#include "pipeline.h"
#include "progress.h"
#include "provenance.h"

#include <morphreg/common/error.h>
#include <morphreg/pipeline/model_evaluation.h>

#include <nlohmann/json.hpp>

#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
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

/** The evaluation's stages on the console (quiet: none). */
class EvaluationConsole : public ModelEvaluationObserver
{
public:
  explicit EvaluationConsole (bool quiet) : quiet_ (quiet) {}

  void
  stageStarted (const std::string& stage, int count) override
  {
    progress_.emplace (stage, count, quiet_);
  }

  void
  stepDone (int done) override
  {
    progress_->step (done);
  }

  void
  stageFinished () override
  {
    progress_->finish ();
  }

private:
  bool quiet_;
  std::optional<Progress> progress_;
};

/** Every measure per component count. */
nlohmann::json
evaluate (const EvaluateModelOptions& options, const MorphableModel& model)
{
  ModelEvaluationSettings settings;
  settings.samples = options.samples;
  settings.seed = options.seed;
  settings.components = options.components;
  EvaluationConsole console (options.quiet);
  return evaluateModel (model, options.model, options.meshes, options.training, settings, &console);
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
