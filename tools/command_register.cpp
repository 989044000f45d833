// SPDX-License-Identifier: BSD-3-Clause
// `morphreg register`: a scan + a model file -> the fitted mesh (vertex colours: the scan's or the residual; vertex
// quality: the residual), a JSON report and optionally a screenshot of the fit; with --truth, the fit's vertex error
// against the true mesh.
#include "commands.h"
#include "mesh_output.h"
#include "option_checks.h"
#include "pipeline.h"
#include "progress.h"
#include "display_inputs.h"
#include "provenance.h"
#include "scan_colours.h"

#include <morphreg/common/cloud_matrix.h>
#include <morphreg/common/distance_statistics.h>
#include <morphreg/common/error.h>
#include <morphreg/common/length_unit.h>
#include <morphreg/common/head_scale_unit.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/depth_image_io.h>
#include <morphreg/io/file_format.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/landmark_io.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/io/model_io.h>
#include <morphreg/io/output_plan.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/registration/iteration_progress.h>
#include <morphreg/registration/morphable_icp.h>
#include <morphreg/registration/registration_result_json.h>
#include <morphreg/registration/registration_settings.h>
#include <morphreg/registration/scan_units.h>
#include <morphreg/registration/scan_checks.h>
#include <morphreg/common/colour_map.h>
#include <morphreg/visualization/convergence_plot.h>
#include <morphreg/visualization/registration_visualizer.h>

#include <pcl/common/io.h>

#include <algorithm>
#include <limits>
#include <chrono>
#include <cstdlib>
#include <cmath>
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

/** \a scan without its missing points (PCL marks them NaN). An infinite coordinate is no such mark but a broken
 *  file: those points stay for requireRegistrableScan to reject. */
void
dropMissingPoints (pcl::PointCloud<pcl::PointNormal>& scan)
{
  const auto missing = [] (const pcl::PointNormal& p) {
    return std::isnan (p.x) || std::isnan (p.y) || std::isnan (p.z);
  };
  scan.erase (std::remove_if (scan.begin (), scan.end (), missing), scan.end ());
}

/** The scan landmarks of the file that the model also has; the others are named on \a warnings and skipped. The
 *  landmarks must lie on the \a scan (in mm). */
LandmarkPositions
modelLandmarks (const RegisterOptions& options, const MorphableModel& model,
                const pcl::PointCloud<pcl::PointNormal>& scan, std::ostream& warnings)
{
  LandmarkPositions landmarks = loadLandmarks (options.landmarks);
  requireLandmarksOnScan (landmarks, pointsOf (scan), options.landmarks);
  std::string skipped;
  for (const std::string& id : keepKnownLandmarks (landmarks, model.landmarks ()))
    skipped += " " + id;
  if (!skipped.empty () && !options.quiet)
    warnings << options.landmarks << ": the model has no landmark" << skipped << "; using the other "
             << landmarks.size () << '\n';
  if (landmarks.empty ())
    throw InvalidInputError (options.landmarks + ": none of its landmarks is on the model " + options.model);
  return landmarks;
}

/** Prints one progress line per iteration: the kept correspondences and their RMS distance. */
void
showIterations (Icp& icp, const Progress& progress)
{
  watchIterations (icp, [&progress] (int iteration, std::size_t correspondences, double rms) {
    std::ostringstream detail;
    detail << ' ' << correspondences << " correspondences, RMS " << std::fixed << std::setprecision (3) << rms << " mm";
    progress.step (iteration, detail.str ());
  });
}

/** The registration settings of the report, with the landmark file. */
nlohmann::json
settingsJson (const RegisterOptions& options)
{
  nlohmann::json settings = toJson (static_cast<const RegistrationSettings&> (options));
  settings["landmarks"] = options.landmarks;
  return settings;
}
/** Vertex distances between the fit and the true mesh (model topology, scan frame), over every vertex and over
 *  the vertices the scan covers (those with a residual); printed and reported. */
nlohmann::json
truthErrors (const RegisterOptions& options, const TriangleMesh& fitted, const Eigen::VectorXd& residuals,
             std::ostream& out)
{
  const TriangleMesh truth = loadTriangleMesh (options.truth);
  requireSameTopology (fitted, truth, options.truth);
  const Eigen::VectorXd errors = (fitted.vertices - truth.vertices).colwise ().norm ().transpose ();
  const Eigen::VectorXd covered = residuals.array ().isFinite ().select (errors, NAN);
  nlohmann::json report = distanceStatistics (errors);
  report["covered_by_scan"] = distanceStatistics (covered);
  report["file"] = options.truth;
  out << "vertex RMS against the truth " << options.truth << ": " << std::fixed << std::setprecision (3)
      << report["rms"].get<double> () << " mm (mean " << report["mean"].get<double> () << ", max "
      << report["max"].get<double> () << "); over the " << report["covered_by_scan"]["count"]
      << " vertices the scan covers: RMS " << report["covered_by_scan"]["rms"].get<double> () << " mm\n"
      << std::defaultfloat;
  return report;
}

/** The fitted model coloured by residual under a sparse sample of the scan's points (small, grey: no moiré), seen
 *  from the fitted face's front-left, the head filling the picture. */
void
saveOverlay (RegistrationVisualizer& viewer, const RegisterOptions& options,
             const pcl::PointCloud<pcl::PointNormal>& scan, const TriangleMesh& fitted,
             const Eigen::VectorXd& residuals, double scale, const Eigen::Matrix4d& pose)
{
  const std::size_t scan_points = static_cast<std::size_t> (options.width) * options.height / 60;
  viewer.addScanOverlay (scan, scan_points, "scan");
  viewer.addResidualHeatMap (fitted, residuals, scale, "residuals");
  viewer.setFramedShapes ({"residuals"});
  const Eigen::Matrix3d linear = pose.topLeftCorner<3, 3> ();
  const Eigen::Matrix3d rotation = linear / std::cbrt (linear.determinant ());
  viewer.resetCamera (rotation * Eigen::Vector3d (0.5, 0.15, 1.0).normalized (), rotation * Eigen::Vector3d::UnitY ());
  viewer.saveScreenshot (options.screenshot, options.width, options.height);
}

/** The overlay (with a viewer) and the convergence plot (if asked), recorded in \a report; returns the seconds. */
double
saveFigures (RegistrationVisualizer* viewer, const RegisterOptions& options, Icp& icp,
             const pcl::PointCloud<pcl::PointNormal>& scan, const TriangleMesh& fitted, double scale,
             nlohmann::json& report)
{
  const auto start = Clock::now ();
  if (viewer) {
    saveOverlay (*viewer, options, scan, fitted, icp.getVertexResiduals (), scale,
                 icp.getFinalTransformation ().cast<double> ());
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
} // namespace

/** The scan as points with normals, without missing points, checked to be registrable (see requireRegistrableScan). */
ScanCloud
loadScan (const RegisterOptions& options)
{
  const std::string& path = options.scan;
  pcl::PointCloud<pcl::PointNormal>::Ptr scan;
  if (options.intrinsics.empty ())
    scan = loadCloud<pcl::PointNormal> (path);
  else { // a depth image: its organised cloud in mm, no normals, no colours
    if (options.colours == "scan")
      throw InvalidInputError ("--colours scan with --depth " + path + ": a depth image has no colours");
    const DepthImage image = loadDepthPng (path);
    DepthIntrinsics camera = loadDepthIntrinsics (options.intrinsics);
    if (camera.width != image.width || camera.height != image.height)
      throw InvalidInputError (path + ": the depth image is " + std::to_string (image.width) + " x " +
                               std::to_string (image.height) + " pixels, the camera of " + options.intrinsics + " " +
                               std::to_string (camera.width) + " x " + std::to_string (camera.height));
    scan.reset (new pcl::PointCloud<pcl::PointNormal>);
    pcl::copyPointCloud (*depthImageToCloud (image.depth, camera), *scan);
    for (auto& point : *scan)
      point.normal_x = point.normal_y = point.normal_z = std::numeric_limits<float>::quiet_NaN ();
  }
  const std::optional<Eigen::Vector3d> viewpoint =
      scan->isOrganized () ? std::optional<Eigen::Vector3d> (scan->sensor_origin_.head<3> ().cast<double> ())
                           : std::nullopt;
  dropMissingPoints (*scan);
  if (scan->empty ())
    throw FormatError (path + ": the scan has no valid (finite) points");
  requireRegistrableScan (pointsOf (*scan), path);
  requireUnitNormals (normalsOf (*scan), path);
  scan->is_dense = true;
  return {scan, viewpoint};
}

/** The scan's unit (given, or guessed from its size against the model mean's) and its coordinates in mm. */
LengthUnitGuess
convertScanToMillimetres (ScanCloud& scan, const RegisterOptions& options, const MorphableModel& model,
                          std::ostream& out)
{
  if (!options.intrinsics.empty () && options.units != "auto" && options.units != "mm")
    throw InvalidInputError ("--units " + options.units + " with --depth: a depth image holds mm");
  const FileFormat format = sniffFileFormat (options.scan);
  if (const auto file_unit = specifiedLengthUnit (format))
    out << "units: " << options.scan << " is " << fileFormatName (format) << ", whose unit is the "
        << toString (*file_unit) << " by specification: converted to mm on reading (x" << millimetresPer (*file_unit)
        << ")\n";
  const std::string units = options.intrinsics.empty () ? options.units : "mm";
  const LengthUnitGuess unit =
      morphreg::convertScanToMillimetres (*scan.cloud, units, model, options.scan, scan.viewpoint.has_value ());
  if (scan.viewpoint)
    *scan.viewpoint *= unit.scale_to_mm;
  if (unit.unit != LengthUnit::millimetre)
    out << "units: the scan's unit is " << toString (unit.unit) << " (" << unit.reason << "); rescaled to mm\n";
  return unit;
}

void
addRegistrationInputs (const RegisterOptions& options, OutputPlan& plan)
{
  plan.addInput (options.scan, options.intrinsics.empty () ? "--scan" : "--depth");
  plan.addInput (options.intrinsics, "--intrinsics");
  plan.addInput (options.model, "--model");
  plan.addInput (options.landmarks, "--landmarks");
  plan.addInput (options.truth, "--truth");
}

std::string
reportPath (const RegisterOptions& options)
{
  return options.report.empty () ? std::filesystem::path (options.out).replace_extension (".json").string ()
                                 : options.report;
}

MorphableModel::Ptr
loadModelFile (const std::string& path, std::ostream& out)
{
  MorphableModel::Ptr model = loadModel (path);
  const auto file_units = model->metadata ().find (kFileUnitsKey);
  if (file_units != model->metadata ().end () && file_units->second.rfind ("mm ", 0) != 0)
    out << "units: the model file " << path << " is in " << file_units->second << '\n';
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
  const char* x_display = std::getenv ("DISPLAY");
  if (!options.convergence_plot.empty () && (x_display == nullptr || *x_display == '\0'))
    throw InvalidInputError ("register --convergence-plot " + options.convergence_plot +
                             ": the plot renders through X and $DISPLAY is unset; run under `xvfb-run -a`");
  const MorphableModel::Ptr model = loadModelFile (options.model, std::cout);
  return commitUnlessBadInput (outputs, [&] {
    return registerScan (options, model, viewer ? &*viewer : nullptr, secondsSince (start), std::cout, std::cerr);
  });
}

namespace
{
/** Writes the report of a fit that lost the scan (it passed its checks, so it is a failed fit, not bad input) and
 *  throws FitCheckFailure.
 */
[[noreturn]] void
reportLostFit (const RegisterOptions& options, std::size_t scan_points, const std::string& lost)
{
  const std::string report_path = reportPath (options);
  nlohmann::json report = {{"status", "failed"},
                           {"checks", {{"passed", false}, {"failures", {lost}}}},
                           {"scan", {{"file", options.scan}, {"points", scan_points}}},
                           {"settings", settingsJson (options)},
                           {"fitted_mesh", nullptr}};
  addProvenance (options, report);
  writeReport (report_path, report);
  throw FitCheckFailure (lost + "; no mesh written (see " + report_path + ")", report);
}

/** The report's description of the scan and how its unit was found. */
nlohmann::json
scanJson (const RegisterOptions& options, std::size_t scan_points, const LengthUnitGuess& unit)
{
  nlohmann::json scan = {{"file", options.scan},
                         {"points", scan_points},
                         {"units", unit.estimated ? "estimated" : toString (unit.unit)},
                         {"unit_detection", options.units == "auto" ? "auto" : "given"},
                         {"unit_reason", unit.reason},
                         {"scale_to_mm", unit.scale_to_mm}};
  const FileFormat format = sniffFileFormat (options.scan);
  if (const auto file_unit = specifiedLengthUnit (format))
    scan["file_unit"] = {{"unit", toString (*file_unit)},
                         {"scale_to_mm", millimetresPer (*file_unit)},
                         {"reason", fileFormatName (format) + "'s unit by specification, converted on reading; units "
                                                              "and scale_to_mm apply after it"}};
  return scan;
}

/** The scan's colours at the fitted \a vertices as options.colours asks (scanColoursAt); none for a depth image,
 *  which has no colours (loadScan refuses --colours scan with it). */
std::optional<VertexColours>
fittedScanColours (const RegisterOptions& options, const LengthUnitGuess& unit, const Eigen::Matrix3Xd& vertices,
                   std::ostream& warnings)
{
  if (!options.intrinsics.empty ())
    return std::nullopt;
  return scanColoursAt (options.scan, unit.scale_to_mm, options.colours, vertices, warnings);
}

/** The JSON report of a finished fit (without its truth errors, screenshot and timings). */
nlohmann::json
fitReport (const RegisterOptions& options, Icp& icp, const MorphableModel& model, const nlohmann::json& scan,
           double colour_scale)
{
  nlohmann::json report = registrationResultJson (icp, model);
  report["scan"] = scan;
  report["model"] = {{"file", options.model}, {"vertices", model.numVertices ()}, {"regions", model.numRegions ()}};
  report["settings"] = settingsJson (options);
  report["residuals_mm"]["colour_scale_max"] = colour_scale;
  report["fitted_mesh"] = options.out;
  addProvenance (options, report);
  return report;
}

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

/** Runs \a icp's fit with progress shown unless quiet; TooFewCorrespondencesError when it loses the scan. */
void
alignScan (Icp& icp, const RegisterOptions& options)
{
  const Progress progress ("registering " + options.scan, options.iterations, options.quiet);
  if (!options.quiet)
    showIterations (icp, progress);
  pcl::PointCloud<pcl::PointNormal> aligned;
  try {
    icp.align (aligned);
  }
  catch (const TooFewCorrespondencesError&) {
    throw;
  }
  catch (const InvalidInputError& e) { // the scan passed the checks before the fit, but the fit cannot use it
    throw InvalidInputError (options.scan + ": cannot be registered: " + e.what ());
  }
  progress.finish (static_cast<int> (icp.getRegistrationReport ().history.size ()));
}

/** A fit of the scan at one scale: the scan in mm at that scale, and the registration, or why it lost the scan. */
struct UnitFit
{
  ScanCloud scan;           ///< the scan in mm at unit.scale_to_mm
  LengthUnitGuess unit;     ///< the unit or scale the scan was brought to mm by
  std::unique_ptr<Icp> icp; ///< the finished registration; null when the fit lost the scan
  std::string lost;         ///< why the fit lost the scan (too few correspondences), if it did
  double seconds = 0.0;     ///< the fit's time
};

/** \a scan with its points (and viewpoint) times \a factor. */
ScanCloud
scaledScan (const ScanCloud& scan, double factor)
{
  ScanCloud scaled{pcl::make_shared<pcl::PointCloud<pcl::PointNormal>> (*scan.cloud), scan.viewpoint};
  const auto to_mm = static_cast<float> (factor);
  if (to_mm != 1.0f)
    for (auto& point : *scaled.cloud)
      point.getVector3fMap () *= to_mm;
  if (scaled.viewpoint)
    *scaled.viewpoint *= factor;
  return scaled;
}

/** Registers \a scan (mm) to \a model with the options' settings and landmarks. */
UnitFit
fitScan (const RegisterOptions& options, const MorphableModel::Ptr& model, ScanCloud scan, const LengthUnitGuess& unit,
         std::ostream& warnings)
{
  UnitFit fit{std::move (scan), unit, std::make_unique<Icp> (), "", 0.0};
  Icp& icp = *fit.icp;
  configureRegistration (icp, options, model);
  icp.setTargetViewpoint (fit.scan.viewpoint);
  if (!options.landmarks.empty ())
    icp.setTargetLandmarks (modelLandmarks (options, *model, *fit.scan.cloud, warnings), options.landmark_weight);
  icp.setInputTarget (fit.scan.cloud);
  const auto start = Clock::now ();
  try {
    alignScan (icp, options);
  }
  catch (const TooFewCorrespondencesError& e) {
    fit.lost = e.what ();
    fit.icp.reset ();
  }
  fit.seconds = secondsSince (start);
  return fit;
}

/** The fit's similarity scale (model to scan). */
double
fittedScale (Icp& icp)
{
  return std::cbrt (icp.getFinalTransformation ().topLeftCorner<3, 3> ().cast<double> ().determinant ());
}

/** Whether --units auto looks for the scan's scale in its head: its size is a head in no unit, or the fit at the unit
 *  its size suggested lost the scan or found the head at a size no head has (checkFitPlausibility's scale bounds). */
bool
needsHeadScale (const RegisterOptions& options, const UnitFit& fit)
{
  if (options.units != "auto" || !options.intrinsics.empty ())
    return false;
  if (!fit.unit.recognised || !fit.icp)
    return true;
  const FitPlausibilitySettings limits;
  const double scale = fittedScale (*fit.icp);
  return scale < limits.min_scale || scale > limits.max_scale;
}

/** What the fit at the provisional scale or the final fit found, for the message of a scan refused as no head. */
std::string
whyNoHead (const UnitFit& fit, const MorphableModel& model)
{
  if (!fit.icp)
    return "lost the scan (" + fit.lost + ")";
  std::string failures;
  for (const std::string& failure : checkRegistration (*fit.icp, model).failures)
    failures += (failures.empty () ? "" : "; ") + failure;
  return "failed its checks (" + failures + ")";
}

/** The scan's unit found from its head (--units auto, see needsHeadScale): a fit at a provisional scale measures the
 *  head (provisionalHeadScale), the unit or estimated scale follows from its size (unitFromHeadScale), and the scan
 *  is fitted again at it. When no head is found, the fit at the unit its size suggested stands if there was one;
 *  else the scan is refused (InvalidInputError naming it, its size and what was tried). */
UnitFit
fitAtHeadScale (const RegisterOptions& options, const MorphableModel::Ptr& model, const ScanCloud& as_read,
                UnitFit suggested, std::ostream& out, std::ostream& warnings)
{
  const LengthUnitGuess provisional = provisionalHeadScale (suggested.unit);
  const std::string tried = suggested.unit.recognised ? "read as " + toString (suggested.unit.unit) + ", the fit " +
                                                            whyNoHead (suggested, *model) + "; "
                                                      : "";
  UnitFit measured = fitScan (options, model, scaledScan (as_read, provisional.scale_to_mm), provisional, warnings);
  std::string failure = "at the provisional scale the fit " + whyNoHead (measured, *model);
  // the global alignment searches heads of 0.6-1.6 times the model: a fit far outside found no head to measure
  constexpr double kSmallestHead = 0.5, kLargestHead = 2.0;
  if (measured.icp && (fittedScale (*measured.icp) < kSmallestHead || fittedScale (*measured.icp) > kLargestHead))
    measured.icp.reset ();
  if (measured.icp) {
    const FitPlausibilitySettings limits;
    const LengthUnitGuess unit =
        unitFromHeadScale (provisional, fittedScale (*measured.icp), limits.min_scale, limits.max_scale);
    UnitFit final = fitScan (options, model, scaledScan (as_read, unit.scale_to_mm), unit, warnings);
    final.unit.reason = provisional.reason + "; " + unit.reason;
    if (final.icp && checkRegistration (*final.icp, *model).plausible) {
      out << "units: " << options.scan << ": " << final.unit.reason << "; rescaled to mm\n";
      return final;
    }
    std::ostringstream at;
    at << unit.reason << "; at x" << std::setprecision (4) << unit.scale_to_mm << " to mm the fit "
       << whyNoHead (final, *model);
    failure = at.str ();
  }
  if (suggested.unit.recognised)
    return suggested;
  throw InvalidInputError (options.scan + ": no head found, so its unit cannot be estimated: " + provisional.reason +
                           "; " + tried + failure + ". Give --units if it is a head");
}
} // namespace

nlohmann::json
registerScan (const RegisterOptions& options, const MorphableModel::Ptr& model, RegistrationVisualizer* viewer,
              double model_seconds, std::ostream& out, std::ostream& warnings, const FitFollowUp& follow_up)
{
  const auto start = Clock::now ();
  const ScanCloud as_read = loadScan (options);
  ScanCloud loaded = scaledScan (as_read, 1.0);
  const LengthUnitGuess guess = convertScanToMillimetres (loaded, options, *model, out);
  UnitFit fit{std::move (loaded), guess, nullptr, "", 0.0};
  const double load_seconds = model_seconds + secondsSince (start);
  if (guess.recognised || options.units != "auto")
    fit = fitScan (options, model, std::move (fit.scan), guess, warnings);
  if (needsHeadScale (options, fit))
    fit = fitAtHeadScale (options, model, as_read, std::move (fit), out, warnings);
  if (!fit.icp)
    reportLostFit (options, fit.scan.cloud->size (), fit.lost);
  Icp& icp = *fit.icp;
  const auto& scan = fit.scan.cloud;
  const LengthUnitGuess& unit = fit.unit;
  const double fit_seconds = fit.seconds;

  const auto write_start = Clock::now ();
  const TriangleMesh fitted{icp.getFittedVertices (), model->triangles ()};
  const Eigen::VectorXd& residuals = icp.getVertexResiduals ();
  const double scale = residualColourScale (residuals, options.colour_max);
  const auto scan_colours = fittedScanColours (options, unit, fitted.vertices, warnings);
  savePolygonMesh (
      options.out,
      toPolygonMesh (fitted, scan_colours ? *scan_colours : residualColours (residuals, scale), residuals));
  const double write_seconds = secondsSince (write_start);

  nlohmann::json report = fitReport (options, icp, *model, scanJson (options, scan->size (), unit), scale);
  report["fitted_mesh_colours"] = scan_colours ? "scan" : "residual";
  if (!options.truth.empty ())
    report["truth_vertex_error_mm"] = truthErrors (options, fitted, residuals, out);
  const double figure_seconds = saveFigures (viewer, options, icp, *scan, fitted, scale, report);
  if (follow_up)
    follow_up (*scan, fitted, report);
  report["timings_s"] = {{"load", load_seconds},
                         {"fit", fit_seconds},
                         {"write_mesh", write_seconds},
                         {"figures", figure_seconds},
                         {"total", model_seconds + secondsSince (start)}};
  // Written last and atomically: a report on disk means the scan's outputs are complete (batch resume trusts it).
  writeReport (reportPath (options), report);
  concludeFit (options, icp.getRegistrationReport (), report, fit_seconds, scale, out);
  return report;
}

namespace
{
/** The robust loss and the PCL rejector chain of addRegistrationOptions. */
void
addRobustnessOptions (CLI::App* command, RegisterOptions& options)
{
  command->add_option ("--loss", options.loss, "robust loss: none, huber, tukey")
      ->check (CLI::IsMember ({"none", "huber", "tukey"}))
      ->capture_default_str ();
  command->add_option ("--loss-scale", options.loss_scale, "robust loss width (mm, 0 = from the residuals' MAD)")
      ->check (nonNegative ())
      ->capture_default_str ();
  command
      ->add_option ("--reject-distance", options.reject_distance,
                    "reject correspondences farther than this (mm; pcl CorrespondenceRejectorDistance)")
      ->check (positive ());
  command
      ->add_option ("--reject-median", options.reject_median,
                    "reject beyond FACTOR x the median distance (CorrespondenceRejectorMedianDistance)")
      ->check (positive ());
  command->add_flag ("--reject-one-to-one", options.reject_one_to_one,
                     "keep one correspondence per scan point (CorrespondenceRejectorOneToOne)");
  command
      ->add_option ("--reject-trimmed", options.reject_trimmed,
                    "keep this fraction of the closest correspondences (CorrespondenceRejectorTrimmed)")
      ->check (inRange (0.01, 1.0));
}

/** The scan's unit and smoothing (--units, --target-smoothing) of addRegistrationOptions. */
void
addScanTreatmentOptions (CLI::App* command, RegisterOptions& options)
{
  command
      ->add_option ("--target-smoothing", options.target_smoothing,
                    "fit to each scan point projected onto its neighbours' plane: on, off or auto (on for noisy scans "
                    "such as depth-camera frames; the report's target_surface says what was done)")
      ->check (CLI::IsMember ({"auto", "on", "off"}))
      ->capture_default_str ();
  command->add_flag_callback (
      "--no-target-smoothing", [&options] { options.target_smoothing = "off"; }, "the same as --target-smoothing off");
  command
      ->add_option ("--units", options.units,
                    "the scan's length unit: auto (from its size; a scan in no unit: its scale estimated from the "
                    "head), mm, cm, m or in (glTF/GLB scans: the unit after reading, which converts glTF's metres "
                    "to mm)")
      ->check (CLI::IsMember ({"auto", "mm", "cm", "m", "in"}))
      ->capture_default_str ();
}
} // namespace

void
addRegistrationOptions (CLI::App* command, RegisterOptions& options)
{
  command->add_option ("--width", options.width, "screenshot width (pixels)")
      ->check (inRange (16, 8192))
      ->capture_default_str ();
  command->add_option ("--height", options.height, "screenshot height (pixels)")
      ->check (inRange (16, 8192))
      ->capture_default_str ();
  command->add_option ("--iterations", options.iterations, "ICP iterations, similarity and shape stages together")
      ->check (inRange (1, 10000))
      ->capture_default_str ();
  command
      ->add_option ("--similarity-iterations", options.similarity_iterations,
                    "at most this many iterations fit the similarity alone before the shape joins")
      ->check (inRange (1, 10000))
      ->capture_default_str ();
  command->add_option ("--max-distance", options.max_distance, "max correspondence distance (mm, 0 = no limit)")
      ->check (nonNegative ())
      ->capture_default_str ();
  command
      ->add_option ("--components", options.components,
                    "shape components per region: one count for all, or one per region (default: every component "
                    "the model has, at most 60 per region)")
      ->check (nonNegative ());
  command->add_flag ("--point-to-plane,!--point-to-point", options.point_to_plane,
                     "point-to-plane residuals along the scan normals (default) or point-to-point");
  command
      ->add_option ("--tangential-weight", options.tangential_weight,
                    "share of the point-to-point term kept along the tangent plane (point-to-plane)")
      ->check (inRange (0.0, 1.0))
      ->capture_default_str ();
  command
      ->add_option ("--shape-prior", options.shape_prior,
                    "weight of the shape prior (coefficients in prior standard deviations)")
      ->check (nonNegative ())
      ->capture_default_str ();
  command
      ->add_option ("--refinement-prior", options.refinement_prior,
                    "refine over all --components at this shape prior, after a first phase over at most 10 per "
                    "region at --shape-prior (e.g. 0.5 with many components: fits that follow the scan closely)")
      ->check (nonNegative ());
  command
      ->add_option ("--refinement-smoothness", options.refinement_smoothness,
                    "lambda_1 of the refinement of --refinement-prior (less for models whose regions cannot agree on "
                    "the scan, e.g. 0.1 with ICT-FaceKit)")
      ->check (nonNegative ())
      ->capture_default_str ();
  command
      ->add_option ("--landmark-weight", options.landmark_weight,
                    "one landmark counts as this many correspondences in the fit (0: the landmarks only place the "
                    "start)")
      ->check (nonNegative ())
      ->capture_default_str ();
  addScanTreatmentOptions (command, options);
  command->add_flag ("--area-weighting", options.area_weighting,
                     "weigh model vertices by their surface area (models with uneven vertex density, e.g. ICT)");
  addRobustnessOptions (command, options);
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
