// SPDX-License-Identifier: BSD-3-Clause
// `morphreg model-info`: what a model file holds (regions, components, variances, landmarks, the file's unit), as
// text or JSON.
#include "commands.h"
#include "provenance.h"

#include <morphreg/io/model_description.h>
#include <morphreg/io/model_io.h>

#include <nlohmann/json.hpp>

#include <iomanip>
#include <iostream>
#include <memory>
#include <numeric>
#include <sstream>

namespace morphreg
{
namespace tools
{
namespace
{
struct ModelInfoOptions
{
  std::string model;
  bool json = false;
};

/** "12.5 3.1 ... (40 in all)": the first few variances of a list. */
std::string
varianceList (const nlohmann::json& json)
{
  const auto variances = json.get<std::vector<double>> ();
  std::ostringstream text;
  text << std::setprecision (4);
  const std::size_t shown = std::min<std::size_t> (variances.size (), 5);
  for (std::size_t k = 0; k < shown; ++k)
    text << (k ? " " : "") << variances[k];
  if (variances.size () > shown)
    text << " ... (sum " << std::accumulate (variances.begin (), variances.end (), 0.0) << ")";
  return variances.empty () ? "none" : text.str ();
}

void
printText (const nlohmann::json& info)
{
  std::cout << info["file"].get<std::string> () << ": " << info["vertices"] << " vertices, " << info["triangles"]
            << " triangles, units " << info["units"].get<std::string> () << '\n'
            << "regions (" << info["regions"].size () << "):\n";
  for (const auto& region : info["regions"])
    std::cout << "  " << region["name"].get<std::string> () << ": " << region["vertices"] << " vertices, "
              << region["components"] << " components, variances (mm^2) " << varianceList (region["variances_mm2"])
              << '\n';
  std::cout << "global PCA: " << info["global_pca"]["components"] << " components, variances (mm^2) "
            << varianceList (info["global_pca"]["variances_mm2"]) << '\n'
            << "landmarks (" << info["landmarks"].size () << "):";
  for (const auto& [id, vertex] : info["landmarks"].items ())
    std::cout << ' ' << id << '=' << vertex;
  std::cout << "\nthe file's unit: " << info["file_units"].get<std::string> () << '\n';
}
} // namespace

void
registerModelInfoCommand (CLI::App& app)
{
  auto options = std::make_shared<ModelInfoOptions> ();
  CLI::App* command = app.add_subcommand ("model-info", "print a model file's regions, components, variances and "
                                                        "landmarks");
  command->add_option ("-m,--model", options->model, "model file (.h5: build-model, statismo or BFM-2017)")
      ->required ();
  command->add_flag ("--json", options->json, "print JSON (every variance) instead of text");
  command->callback ([options] () {
    const nlohmann::json info = describeModel (*loadModel (options->model), options->model);
    if (options->json)
      std::cout << stamped (info).dump (2) << '\n';
    else
      printText (info);
  });
}

} // namespace tools
} // namespace morphreg
