// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The build-model and register steps as functions on files, shared by their subcommands and by demo.
#include "scan_resampling.h"

#include <morphreg/model/model_builder.h>
#include <morphreg/model/morphable_model.h>
#include <morphreg/io/output_plan.h>
#include <morphreg/io/output_transaction.h>
#include <morphreg/pipeline/model_building.h>
#include <morphreg/pipeline/scan_file_registration.h>

#include <nlohmann/json.hpp>

#include <CLI/CLI.hpp>

#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace morphreg
{
class RegistrationVisualizer;

namespace tools
{
/** Inputs and outputs of `morphreg register`; the registration settings (and the fitted mesh's colours: colours,
 *  colour_max) are the library's, by the same names. */
struct RegisterOptions : ScanFileSettings
{
  std::string scan, model, out = "fitted.ply";
  std::string scans;            ///< batch mode: a folder of scans or a manifest CSV (see morphreg/io/scan_manifest.h)
  std::string report;           ///< empty: next to out, with .json
  std::string screenshot;       ///< empty: none
  std::string convergence_plot; ///< PNG of the RMS distance per iteration; empty: none
  int width = 1280, height = 960;
  std::string landmarks, truth;
  /** With a depth image as the scan (a 16-bit PNG in mm): its camera's intrinsics (JSON; depth_image_io.h). */
  std::string intrinsics;
  bool quiet = false;
};

/** The registration of `build-model --from-scans`: the library's (ModelFromScansSettings::defaultRegistration). */
inline RegisterOptions
fromScansRegistration ()
{
  RegisterOptions options;
  static_cast<RegistrationSettings&> (options) = ModelFromScansSettings::defaultRegistration ();
  options.colours = "residual"; // the fits are a step towards the model: no time spent on the scans' colours
  return options;
}

/** Thrown when a registration finished but failed its plausibility checks (exit code 4); the outputs are written
 *  (committed by the caller's OutputTransaction: commitUnlessBadInput). */
class FitCheckFailure : public std::runtime_error
{
public:
  /** \a report: the report written, marked failed (null where none is). */
  FitCheckFailure (const std::string& message, nlohmann::json report = nullptr)
    : std::runtime_error (message), report_ (std::move (report))
  {}

  const nlohmann::json&
  report () const
  {
    return report_;
  }

private:
  nlohmann::json report_;
};

/** Runs \a run and commits \a outputs when it succeeds or throws FitCheckFailure (a fit that failed its checks has
 *  its outputs written on purpose: the report says why it failed); on any other failure the outputs roll back. */
template <typename Run>
auto
commitUnlessBadInput (OutputTransaction& outputs, Run run) -> decltype (run ())
{
  try {
    auto result = run ();
    outputs.commit ();
    return result;
  }
  catch (const FitCheckFailure&) {
    outputs.commit ();
    throw;
  }
}

/** Loads a model file (loadModel: in mm whatever the file's unit) and says on \a out when the file was in another
 *  unit and converted. */
MorphableModel::Ptr
loadModelFile (const std::string& path, std::ostream& out);

/** Registers the scan to the model and writes the fitted mesh, the report and the screenshot; returns the report. */
nlohmann::json
registerScanFile (const RegisterOptions& options);

/** registerScanFile() with the model already loaded (\a model_seconds it took, counted in the report's load time)
 *  and the viewer already open (nullptr: no screenshot); progress and results go to \a out, warnings (landmarks
 *  the model lacks) to \a warnings; \a follow_up, if given, runs on the fit before the report is written. The fitted
 *  mesh and then the report are written atomically, so a report on disk means complete outputs. Throws
 *  FitCheckFailure after writing them if the fit failed its checks.
 */
nlohmann::json
registerScan (const RegisterOptions& options, const MorphableModel::Ptr& model, RegistrationVisualizer* viewer,
              double model_seconds, std::ostream& out, std::ostream& warnings, const FitFollowUp& follow_up = {});

/** Adds the files a registration reads (--scan, --model, --landmarks, --truth) to \a plan. */
void
addRegistrationInputs (const RegisterOptions& options, OutputPlan& plan);

/** Settings of `register --scans` beyond the single-scan ones. */
struct BatchOptions
{
  std::string out_dir;       ///< per-scan outputs <id>.ply and <id>.json, and the summary
  int jobs = 0;              ///< scans registered at once; 0: every core
  std::string shard;         ///< "I/N", "auto" (Slurm job array) or empty (every scan)
  bool retry_failed = false; ///< register again the scans whose last attempt failed
};

/** Adds --scans, --out-dir, --jobs, --shard and --retry-failed to \a command; returns the --scans option. */
CLI::Option*
addBatchOptions (CLI::App* command, RegisterOptions& options, BatchOptions& batch);

/** Registers every scan of options.scans (its shard) with the library's BatchRegistration, printing its progress;
 *  see `morphreg register --help`. Throws FitCheckFailure naming the summary if any scan failed; exits 130 after
 *  a Ctrl-C. */
void
registerScanBatch (const RegisterOptions& options, const BatchOptions& batch);

/** Adds the screenshot size and the MorphableICP settings (iterations, distances, components, loss, rejectors)
 *  to \a command. */
void
addRegistrationOptions (CLI::App* command, RegisterOptions& options);
/** Inputs and settings of `morphreg build-model`; the settings are the library's (model_building.h). */
struct BuildModelOptions
{
  std::vector<std::string> meshes; ///< mesh files in correspondence
  std::string directory;           ///< a folder of meshes (readMeshFolder)
  std::string regions;             ///< region label file; empty: one global region
  std::string landmark_vertices;   ///< landmark vertex file; empty: none
  std::string ict_directory;       ///< ICT-FaceKit folder: the 7-region ICT model instead of meshes
  std::string from_scans;          ///< a folder of raw scans or a manifest CSV (morphreg/io/scan_manifest.h)
  std::string report_dir;          ///< from_scans: the per-scan outputs and summary (default: <out>_scans)
  RegisterOptions registration = fromScansRegistration (); ///< from_scans: its model registers the scans
  ResamplingOptions resampling;                            ///< from_scans: the resampling of each fit
  ModelFromIctSettings ict;                                ///< ict_directory: samples and seed
  std::string out = "model.h5";
  ModelBuilderSettings settings;
  bool quiet = false;
};

/** Builds and saves the model; returns a summary for reports. */
nlohmann::json
buildModelFile (const BuildModelOptions& options);

} // namespace tools
} // namespace morphreg
