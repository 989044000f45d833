// SPDX-License-Identifier: BSD-3-Clause
// `morphreg register`: a scan + a model file -> the fitted mesh (vertex colours: the scan's or the residual; vertex
// quality: the residual), a JSON report and optionally a screenshot of the fit; with --truth, the fit's vertex error
// against the true mesh.
#include "commands.h"
#include "mesh_output.h"
#include "option_checks.h"
#include "pipeline.h"
#include "progress.h"
#include "provenance.h"
#include "table_options.h"

#include <morphreg/common/error.h>
#include <morphreg/io/model_io.h>
#include <morphreg/io/output_plan.h>
#include <morphreg/pipeline/scan_colours.h>
#include <morphreg/pipeline/scan_input.h>
#include <morphreg/pipeline/scan_registration.h>
#include <morphreg/registration/morphable_icp.h>
#include <morphreg/registration/registration_options.h>
#include <morphreg/registration/registration_settings.h>
#include <morphreg/visualization/convergence_plot.h>
#include <morphreg/visualization/fit_layers.h>
#include <morphreg/visualization/registration_visualizer.h>
#include <morphreg/visualization/x_display.h>

#include <chrono>
#include <filesystem>
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
using Icp = MorphableICP<pcl::PointNormal>;
using Clock = std::chrono::steady_clock;

double
secondsSince (Clock::time_point start)
{
  return std::chrono::duration<double> (Clock::now () - start).count ();
}

/** The fit's vertex distances to the true mesh (truthVertexErrors) on \a out. */
void
printTruthErrors (const nlohmann::json& report, std::ostream& out)
{
  out << "vertex RMS against the truth " << report["file"].get<std::string> () << ": " << std::fixed
      << std::setprecision (3) << report["rms"].get<double> () << " mm (mean " << report["mean"].get<double> ()
      << ", max " << report["max"].get<double> () << "); over the " << report["covered_by_scan"]["count"]
      << " vertices the scan covers: RMS " << report["covered_by_scan"]["rms"].get<double> () << " mm\n"
      << std::defaultfloat;
}

/** The overlay (with a viewer) and the convergence plot (if asked), recorded in \a report; returns the seconds. */
double
saveFigures (RegistrationVisualizer* viewer, const RegisterOptions& options, Icp& icp,
             const pcl::PointCloud<pcl::PointNormal>& scan, const TriangleMesh& fitted, double scale,
             nlohmann::json& report)
{
  const auto start = Clock::now ();
  if (viewer) {
    saveFitOverlay (*viewer, scan, fitted, icp.getVertexResiduals (), scale,
                    icp.getFinalTransformation ().cast<double> (), options.screenshot, options.width, options.height);
    report["screenshot"] = {{"file", options.screenshot}, {"width", options.width}, {"height", options.height}};
  }
  if (!options.convergence_plot.empty ()) {
    const int width = 800, height = 500;
    saveConvergencePlot (options.convergence_plot, icp.getRegistrationReport (),
                         "registration of " + std::filesystem::path (options.scan).filename ().string (), width,
                         height);
    report["convergence_plot"] = {{"file", options.convergence_plot}, {"width", width}, {"height", height}};
  }
  return secondsSince (start);
}

void
runRegister (const RegisterOptions& options, const BatchOptions& batch)
{
  if (options.scans.empty ())
    registerScanFile (options);
  else
    registerScanBatch (options, batch);
}

/** The report file of a registration: --report, else the --out path with .json. */
std::string
reportPath (const RegisterOptions& options)
{
  return options.report.empty () ? std::filesystem::path (options.out).replace_extension (".json").string ()
                                 : options.report;
}

} // namespace

void
addRegistrationInputs (const RegisterOptions& options, OutputPlan& plan)
{
  plan.addInput (options.scan, options.intrinsics.empty () ? "--scan" : "--depth");
  plan.addInput (options.intrinsics, "--intrinsics");
  plan.addInput (options.model, "--model");
  plan.addInput (options.landmarks, "--landmarks");
  plan.addInput (options.truth, "--truth");
}

MorphableModel::Ptr
loadModelFile (const std::string& path, std::ostream& out)
{
  MorphableModel::Ptr model = loadModel (path);
  if (const std::string message = modelFileUnitsMessage (*model, path); !message.empty ())
    out << message << '\n';
  return model;
}

nlohmann::json
registerScanFile (const RegisterOptions& options)
{
  const auto start = Clock::now ();
  OutputPlan plan;
  addRegistrationInputs (options, plan);
  plan.addOutput (options.out, "--out");
  plan.addOutput (reportPath (options), options.report.empty () ? "the report, --out with .json" : "--report");
  if (!options.screenshot.empty ())
    plan.addOutput (options.screenshot, "--screenshot");
  if (!options.convergence_plot.empty ())
    plan.addOutput (options.convergence_plot, "--convergence-plot");
  plan.check ();
  OutputTransaction outputs (plan.outputs ());
  // Without X the screenshot would fail after the fit: open the offscreen viewer first.
  std::optional<RegistrationVisualizer> viewer;
  if (!options.screenshot.empty ())
    viewer.emplace (RegistrationVisualizer::Display::Offscreen);
  if (!options.convergence_plot.empty ())
    requireXDisplay ("register --convergence-plot " + options.convergence_plot);
  const MorphableModel::Ptr model = loadModelFile (options.model, std::cout);
  return commitUnlessBadInput (outputs, [&] {
    return registerScan (options, model, viewer ? &*viewer : nullptr, secondsSince (start), std::cout, std::cerr);
  });
}

namespace
{
/** Progress, unit findings and warnings of a registration on the console (quiet: the findings alone). */
class ConsoleObserver : public RegistrationObserver
{
public:
  ConsoleObserver (bool quiet, std::ostream& out, std::ostream& warnings)
    : quiet_ (quiet), out_ (out), warnings_ (warnings)
  {}

  void
  fitStarted (const std::string& scan_name, int max_iterations) override
  {
    progress_.emplace ("registering " + scan_name, max_iterations, quiet_);
  }

  void
  iterationDone (int iteration, std::size_t correspondences, double rms) override
  {
    if (quiet_)
      return;
    std::ostringstream detail;
    detail << ' ' << correspondences << " correspondences, RMS " << std::fixed << std::setprecision (3) << rms << " mm";
    progress_->step (iteration, detail.str ());
  }

  void
  fitFinished (int iterations) override
  {
    progress_->finish (iterations);
  }

  void
  message (const std::string& text) override
  {
    out_ << text << '\n';
  }

  void
  warning (const std::string& text) override
  {
    if (!quiet_)
      warnings_ << text << '\n';
  }

private:
  bool quiet_;
  std::ostream& out_;
  std::ostream& warnings_;
  std::optional<Progress> progress_;
};

/** The fit's one-paragraph summary on \a out; throws FitCheckFailure when the report failed its checks. */
void
concludeFit (const RegisterOptions& options, const IcpReport& icp_report, const nlohmann::json& report,
             double fit_seconds, double colour_scale, std::ostream& out)
{
  const std::string report_path = reportPath (options);
  std::ostringstream colours;
  if (report["fitted_mesh_colours"] == "scan")
    colours << kScanColoursText;
  else
    colours << "residual, 0-" << colour_scale << " mm";
  out << "registered " << options.scan << " in " << icp_report.history.size () << " iterations ("
      << toString (icp_report.termination) << ", " << fit_seconds << " s): scan-to-model RMS " << icp_report.fitness_rms
      << " mm over " << icp_report.correspondences << " correspondences\n"
      << "wrote " << options.out << ' ' << meshContents (options.out, colours.str (), "residual in mm") << ", "
      << report_path << (report.contains ("screenshot") ? ", " + options.screenshot : std::string ())
      << (report.contains ("convergence_plot") ? ", " + options.convergence_plot : std::string ()) << '\n';
  if (report["checks"]["passed"].get<bool> ())
    return;
  std::string reasons;
  for (const nlohmann::json& failure : report["checks"]["failures"])
    reasons += (reasons.empty () ? "" : "; ") + failure.get<std::string> ();
  throw FitCheckFailure (reasons + " (see " + report_path + ")", report);
}

/** The files of the options' registration. */
ScanFiles
scanFiles (const RegisterOptions& options)
{
  return {options.scan, options.landmarks, options.model, options.out, reportPath (options)};
}

/** Truth errors and figures (the single-scan extras) and then \a follow_up, on a finished fit. */
FitFollowUp
registerFollowUp (const RegisterOptions& options, RegistrationVisualizer* viewer, std::ostream& out,
                  const FitFollowUp& follow_up)
{
  return [&options, viewer, &out, follow_up] (const ScanRegistrationOutcome& fit, const TriangleMesh& fitted,
                                              nlohmann::json& report) {
    if (!options.truth.empty ()) {
      report["truth_vertex_error_mm"] = truthVertexErrors (fitted, fit.icp->getVertexResiduals (), options.truth);
      printTruthErrors (report["truth_vertex_error_mm"], out);
    }
    const double scale = report["residuals_mm"]["colour_scale_max"].get<double> ();
    report["timings_s"]["figures"] = saveFigures (viewer, options, *fit.icp, *fit.scan.cloud, fitted, scale, report);
    if (follow_up)
      follow_up (fit, fitted, report);
  };
}
} // namespace

nlohmann::json
registerScan (const RegisterOptions& options, const MorphableModel::Ptr& model, RegistrationVisualizer* viewer,
              double model_seconds, std::ostream& out, std::ostream& warnings, const FitFollowUp& follow_up)
{
  const auto start = Clock::now ();
  const ScanInput scan = readScanOrDepthImage (options.scan, options.intrinsics, options.colours, options.units);
  ConsoleObserver observer (options.quiet, out, warnings);
  ScanFileSettings settings = options;
  if (!options.intrinsics.empty ())
    settings.colours = "residual"; // a depth image has no colours (readScanOrDepthImage refuses colours scan)
  ScanFileRegistration registration (model, settings);
  registration.setObserver (&observer);
  registration.setReportFields ({{"morphreg", provenanceJson ()}});
  const ScanFileOutcome outcome =
      registration.registerScan (scan, scanFiles (options), registerFollowUp (options, viewer, out, follow_up),
                                 model_seconds + secondsSince (start));
  if (outcome.fit.lostScan ())
    throw FitCheckFailure (outcome.fit.lost + "; no mesh written (see " + reportPath (options) + ")", outcome.report);
  concludeFit (options, outcome.fit.icp->getRegistrationReport (), outcome.report, outcome.fit.fit_seconds,
               outcome.colour_scale, out);
  return outcome.report;
}

void
addRegistrationOptions (CLI::App* command, RegisterOptions& options)
{
  command->add_option ("--width", options.width, "screenshot width (pixels)")
      ->check (inRange (16, 8192))
      ->capture_default_str ();
  command->add_option ("--height", options.height, "screenshot height (pixels)")
      ->check (inRange (16, 8192))
      ->capture_default_str ();
  for (const RegistrationOption& option : registrationOptions ()) {
    addTableOption<RegistrationSettings> (command, options, option);
    if (option.name == "target_smoothing")
      command->add_flag_callback (
          "--no-target-smoothing", [&options] { options.target_smoothing = "off"; },
          "the same as --target-smoothing off");
  }
}

void
registerRegisterCommand (CLI::App& app)
{
  auto options = std::make_shared<RegisterOptions> ();
  CLI::App* command = app.add_subcommand ("register", "fit a model file to a scan (MorphableICP)");
  auto* scan =
      command->add_option ("-s,--scan", options->scan,
                           "scan (.pcd .ply .obj .stl .off .gltf .glb); its unit: see --units; its colours: --colours");
  auto* depth = command->add_option ("--depth", options->scan,
                                     "a depth camera's image as the scan: a 16-bit PNG of depths in mm (needs "
                                     "--intrinsics)");
  auto* intrinsics =
      command->add_option ("--intrinsics", options->intrinsics,
                           "the depth camera of --depth: JSON with width, height, fx, fy, cx, cy (pixels)");
  depth->excludes (scan)->needs (intrinsics);
  intrinsics->needs (depth);
  command->add_option ("-m,--model", options->model, "model file (.h5, from build-model or statismo)")->required ();
  command
      ->add_option ("-o,--out", options->out,
                    meshOutputHelp ("fitted mesh to write", "see --colours", "residual in mm"))
      ->capture_default_str ();
  command
      ->add_option ("--colours", options->colours,
                    "the fitted mesh's vertex colours: auto (the scan's when it has any, else residual), scan (the "
                    "colour of the nearest scan surface point: vertex colours, or the texture of a textured OBJ or "
                    "glTF; not with --depth), residual (the residual map, as --screenshot shows it)")
      ->check (CLI::IsMember ({"auto", "scan", "residual"}))
      ->capture_default_str ();
  command->add_option ("--report", options->report, "JSON report to write (default: the --out path with .json)");
  command->add_option ("--screenshot", options->screenshot,
                       "PNG of the scan and the fit's residual map (needs X: xvfb-run -a)");
  command->add_option ("--convergence-plot", options->convergence_plot,
                       "PNG plot of the RMS distance to the scan at each iteration (needs X: xvfb-run -a)");
  command->add_option ("-l,--landmarks", options->landmarks,
                       "landmarks on the scan (.pp .json .csv .pts) to start from (Umeyama on >= 3)");
  command->add_option ("--truth", options->truth, "true mesh in the model topology and scan frame: report the error");
  command->add_option ("--colour-max", options->colour_max, "residual colour scale maximum (mm, 0 = 95th percentile)")
      ->check (nonNegative ());
  addRegistrationOptions (command, *options);
  command->add_flag ("-q,--quiet", options->quiet, "no progress output");
  command->footer ("The scan is checked before fitting (at least 100 finite points spread in 3D; else exit 1) and "
                   "the fit after it (scale, coverage, coefficients, shape, distance to the scan, divergence): a "
                   "fit that fails its checks exits 4, with the fitted mesh and the report written and the "
                   "report's status \"failed\"; a fit that loses the scan (too few correspondences) exits 4 with "
                   "the report alone.");
  auto batch = std::make_shared<BatchOptions> ();
  addBatchOptions (command, *options, *batch)->excludes (scan)->excludes (depth);
  command->callback ([options, batch, command, scan, depth] () {
    if (options->scans.empty () && scan->count () == 0 && depth->count () == 0)
      throw CLI::RequiredError ("--scan or --scans");
    runRegister (*options, *batch);
  });
}

} // namespace tools
} // namespace morphreg
