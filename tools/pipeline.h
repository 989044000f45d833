#pragma once
// The build-model and register steps as functions on files, shared by their subcommands and by demo.
#include <morphreg/model/model_builder.h>

#include <nlohmann/json.hpp>

#include <CLI/CLI.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace morphreg
{
namespace tools
{
/** Inputs and settings of `morphreg build-model`. */
struct BuildModelOptions
{
  std::vector<std::string> meshes;   ///< mesh files in correspondence
  std::string directory;             ///< a folder of meshes (population.json's heads if present, else every mesh)
  std::string regions;               ///< region label file; empty: one global region
  std::string landmark_vertices;     ///< landmark vertex file; empty: none
  std::string ict_directory;         ///< ICT-FaceKit folder: the 7-region ICT model instead of meshes
  int ict_samples = 300;
  std::uint64_t seed = 1;
  std::string out = "model.h5";
  ModelBuilderSettings settings;
  bool quiet = false;
};

/** Builds and saves the model; returns a summary for reports. */
nlohmann::json
buildModelFile (const BuildModelOptions& options);

/** Adds the ModelBuilder settings (--components, --variance, --blend-rings, --no-procrustes) to \a command. */
void
addModelBuilderOptions (CLI::App* command, ModelBuilderSettings& settings);

/** Inputs and settings of `morphreg register`. */
struct RegisterOptions
{
  std::string scan, model, out = "fitted.ply";
  std::string report;     ///< empty: next to out, with .json
  std::string screenshot; ///< empty: none
  int width = 1280, height = 960;
  std::string landmarks, truth;
  int iterations = 100;
  int similarity_iterations = 60; ///< at most this many of the iterations fit the similarity alone
  double max_distance = 0.0; ///< mm, 0 = no limit
  std::vector<int> components{10};
  bool point_to_plane = true;
  double tangential_weight = 0.02; ///< point-to-point share kept along the tangent plane
  double shape_prior = 3.0;        ///< lambda_2
  double landmark_weight = 1.0;    ///< one landmark counts as this many correspondences (MorphableICP default)
  bool area_weighting = false;     ///< weigh model vertices by their surface area
  std::string loss = "tukey";
  double loss_scale = 0.0;
  double reject_distance = 0.0;
  double reject_median = 0.0;
  bool reject_one_to_one = false;
  double reject_trimmed = 0.0;
  double colour_max = 0.0; ///< mm, 0 = the 95th percentile of the residuals
  std::string units = "auto";  ///< the scan's unit: auto (guessed from its size), mm, cm, m or in
  bool target_smoothing = true; ///< fit to the scan points projected onto their neighbourhood's plane
  bool quiet = false;
};

/** Thrown when a registration finished but failed its plausibility checks (exit code 4); the outputs are written. */
class FitCheckFailure : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/** Registers the scan to the model and writes the fitted mesh, the report and the screenshot; returns the report. */
nlohmann::json
registerScanFile (const RegisterOptions& options);

/** Adds the screenshot size and the MorphableICP settings (iterations, distances, components, loss, rejectors)
 *  to \a command. */
void
addRegistrationOptions (CLI::App* command, RegisterOptions& options);
} // namespace tools
} // namespace morphreg
