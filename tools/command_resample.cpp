// SPDX-License-Identifier: BSD-3-Clause
// `morphreg resample`: a scan + a model file -> the scan's surface in the model's topology. The scan is registered
// exactly as `register` does it, then ScanResampler moves the fitted mesh's vertices onto the scan along their normals
// and fills the holes; writes the resampled mesh (vertex colours: the scan's, or observed / filled), the fitted mesh
// and one JSON report (the registration's, with the resampling's coverage and holes).
#include "commands.h"
#include "mesh_output.h"
#include "pipeline.h"
#include "provenance.h"
#include "scan_resampling.h"

#include <morphreg/common/error.h>
#include <morphreg/io/output_plan.h>
#include <morphreg/io/output_transaction.h>
#include <morphreg/pipeline/fit_resampling.h>
#include <morphreg/pipeline/scan_colours.h>
#include <morphreg/pipeline/scan_units.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

namespace morphreg
{
namespace tools
{
namespace
{
struct ResampleOptions
{
  RegisterOptions registration; ///< its out is the reference (the fit), its report the resampling's report
  std::string out = "resampled.ply";
  std::string reference = "fit"; ///< fit: registered as register does; landmarks: the mean warped by a TPS
  ResamplingOptions resampling;
};

/** Says what the resampling did. */
void
printResampled (const ResampleOptions& options, const std::optional<ResamplingResult>& result,
                const nlohmann::json& report)
{
  if (!result || options.registration.quiet)
    return;
  std::cout << "resampled " << options.registration.scan << ": " << result->statistics.observed << " of "
            << result->statistics.vertices << " vertices observed (coverage " << result->statistics.coverage << "), "
            << result->statistics.filled << " filled in " << result->statistics.holes.size () << " holes; wrote "
            << options.out << ' '
            << meshContents (
                   options.out,
                   report["resampled_mesh_colours"] == "scan" ? kScanColoursText : "grey observed, orange filled", "")
            << '\n';
}

/** --reference landmarks: the model's mean warped by a thin plate spline onto the scan's landmarks is the reference
 *  (the library's resampleFromLandmarks); writes it, the resampled mesh and the report, and returns the report. */
nlohmann::json
resampleFromLandmarks (const ResampleOptions& options, const MorphableModel& model)
{
  const RegisterOptions& registration = options.registration;
  if (registration.landmarks.empty ())
    throw InvalidInputError ("resample --reference landmarks needs --landmarks (landmarks marked on the scan)");
  if (const std::string message = scanFileUnitMessage (registration.scan); !message.empty ())
    std::cout << message << '\n';
  const LandmarkResampling outcome =
      morphreg::resampleFromLandmarks (model,
                                       {registration.scan,
                                        registration.intrinsics,
                                        registration.landmarks,
                                        registration.out,
                                        {options.out, options.resampling.colours}},
                                       registration.units, options.resampling, std::cerr);
  if (const std::string message = unitConversionMessage (outcome.unit); !message.empty ())
    std::cout << message << '\n';
  printResampled (options, outcome.result, outcome.report);
  writeReport (registration.report, outcome.report);
  return outcome.report;
}

void
runResample (ResampleOptions options)
{
  RegisterOptions& registration = options.registration;
  registration.colours = options.resampling.colours == "state" ? "residual" : options.resampling.colours;
  if (registration.out.empty ())
    registration.out = std::filesystem::path (options.out).replace_extension ().string () + "_fit.ply";
  if (registration.report.empty ())
    registration.report = std::filesystem::path (options.out).replace_extension (".json").string ();
  OutputPlan plan;
  addRegistrationInputs (registration, plan);
  plan.addOutput (options.out, "--out");
  plan.addOutput (registration.out, "--fit-out");
  plan.addOutput (registration.report, "--report");
  plan.check ();
  OutputTransaction outputs (plan.outputs ());
  const MorphableModel::Ptr model = loadModelFile (registration.model, std::cout);
  if (options.reference == "landmarks") {
    commitUnlessBadInput (outputs, [&] { return resampleFromLandmarks (options, *model); });
    return;
  }
  commitUnlessBadInput (outputs, [&] {
    return registerScan (
        registration, model, nullptr, 0.0, std::cout, std::cerr,
        [&] (const ScanRegistrationOutcome& fit, const TriangleMesh& fitted, nlohmann::json& report) {
          printResampled (options,
                          writeResampledFit (*fit.scan.cloud, options.registration.scan, fitted, options.resampling,
                                             {options.out, options.resampling.colours}, report, std::cerr),
                          report);
        });
  });
}

} // namespace

void
registerResampleCommand (CLI::App& app)
{
  auto options = std::make_shared<ResampleOptions> ();
  RegisterOptions& registration = options->registration;
  registration.out.clear ();
  CLI::App* command =
      app.add_subcommand ("resample", "register a scan (as register does) and resample it into the model's topology");
  command
      ->add_option ("-s,--scan", registration.scan,
                    "scan (.pcd .ply .obj .stl .off .gltf .glb); its unit: see --units; its colours: --colours")
      ->required ();
  command->add_option ("-m,--model", registration.model, "model file (.h5, from build-model or statismo)")->required ();
  command->add_option ("-l,--landmarks", registration.landmarks,
                       "landmarks on the scan: the fit's start, or with --reference landmarks the TPS warp's targets");
  command
      ->add_option ("--reference", options->reference,
                    "the reference mesh: fit (the model registered to the scan) or landmarks (the model's mean warped "
                    "by a thin plate spline onto --landmarks, METHOD section 5; no registration)")
      ->check (CLI::IsMember ({"fit", "landmarks"}))
      ->capture_default_str ();
  command->add_option ("-o,--out", options->out, meshOutputHelp ("resampled mesh to write", "see --colours", ""))
      ->capture_default_str ();
  options->resampling.colours = "auto";
  command
      ->add_option ("--colours", options->resampling.colours,
                    "vertex colours of the resampled mesh and the fit: auto (the scan's when it has any, else "
                    "state), scan (the colour of the nearest scan surface point: vertex colours, or the texture of a "
                    "textured OBJ or glTF), state (resampled mesh grey where observed, orange where filled; the fit "
                    "coloured by its residuals)")
      ->check (CLI::IsMember ({"auto", "scan", "state"}))
      ->capture_default_str ();
  command->add_option ("--fit-out", registration.out,
                       "the reference (the fit, or the warped mean) to write (default: the --out path + _fit)");
  command->add_option ("--report", registration.report, "JSON report to write (default: the --out path with .json)");
  addResamplingOptions (command, options->resampling);
  addRegistrationOptions (command, registration);
  command->add_flag ("-q,--quiet", registration.quiet, "no progress output");
  command->footer ("Exit codes as register's: 1 for a scan that cannot be resampled (no overlap with the fit, another "
                   "unit, a hole over more than --max-hole-fraction of the model), its outputs removed; 4 for a fit "
                   "that failed its checks (fit and report written, nothing resampled).");
  command->callback ([options] () { runResample (*options); });
}
} // namespace tools
} // namespace morphreg
