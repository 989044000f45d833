// `morphreg register`: a scan + a model file -> the fitted mesh (vertex colours = residual), a JSON report and
// optionally a screenshot of the fit; with --truth, the fit's vertex error against the true mesh.
#include "commands.h"
#include "distance_statistics.h"
#include "option_checks.h"
#include "output_files.h"
#include "pipeline.h"
#include "progress.h"

#include <morphreg/common/cloud_matrix.h>
#include <morphreg/common/error.h>
#include <morphreg/common/length_unit.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/landmark_io.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/io/model_io.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/registration/fit_plausibility.h>
#include <morphreg/registration/morphable_icp.h>
#include <morphreg/registration/scan_checks.h>
#include <morphreg/common/colour_map.h>
#include <morphreg/visualization/registration_visualizer.h>

#include <pcl/registration/correspondence_rejection_distance.h>
#include <pcl/registration/correspondence_rejection_median_distance.h>
#include <pcl/registration/correspondence_rejection_one_to_one.h>
#include <pcl/registration/correspondence_rejection_trimmed.h>

#include <algorithm>
#include <chrono>
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

/** The colour scale (mm) of the residual map: the given maximum, else the 95th percentile of the residuals. */
double
colourScale (const Eigen::VectorXd& residuals, double requested)
{
  if (requested > 0.0)
    return requested;
  const std::vector<double> finite = sortedFinite (residuals);
  const double percentile = finite.empty () ? 0.0 : finite[(finite.size () * 95) / 100];
  return std::max (percentile, 1e-3);
}

RobustLoss
robustLoss (const std::string& name)
{
  return name == "none" ? RobustLoss::none : name == "huber" ? RobustLoss::huber : RobustLoss::tukey;
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

/** The scan as points with normals, without missing points, checked to be registrable (see requireRegistrableScan). */
pcl::PointCloud<pcl::PointNormal>::Ptr
loadScan (const std::string& path)
{
  auto scan = loadCloud<pcl::PointNormal> (path);
  dropMissingPoints (*scan);
  if (scan->empty ())
    throw FormatError (path + ": the scan has no valid (finite) points");
  requireRegistrableScan (pointsOf (*scan), path);
  scan->is_dense = true;
  return scan;
}

/** Throws when the scan's size, against the model's, is beyond a head's in every unit by orders of magnitude (a
 *  kilometre-sized or micrometre-sized "head"): the file is corrupt or not a scan. */
void
requireHeadScale (const LengthUnitGuess& unit, const std::string& scan)
{
  constexpr double kLargest = 1e4, kSmallest = 1e-5; // a metre scan of a head is about 1e-3 of the model's size
  if (unit.size_ratio <= kLargest && unit.size_ratio >= kSmallest)
    return;
  std::ostringstream message;
  message << std::setprecision (3) << scan << ": the scan is " << unit.size_ratio
          << " times the model's size, which is no head in any unit (mm, cm, m, in); is the file corrupt? ("
          << unit.reason << ")";
  throw InvalidInputError (message.str ());
}

/** The scan's unit (given, or guessed from its size against the model mean's) and its coordinates in mm. */
LengthUnitGuess
convertScanToMillimetres (pcl::PointCloud<pcl::PointNormal>& scan, const RegisterOptions& options,
                          const MorphableModel& model, std::ostream& out)
{
  LengthUnitGuess unit;
  if (options.units == "auto") {
    const Eigen::Map<const Eigen::Matrix3Xd> mean (model.mean ().data (), 3, model.numVertices ());
    const Eigen::Vector3d centroid = mean.rowwise ().mean ();
    const double model_radius = std::sqrt ((mean.colwise () - centroid).colwise ().squaredNorm ().mean ());
    unit = guessLengthUnit (pointsOf (scan), model_radius);
    requireHeadScale (unit, options.scan);
  }
  else {
    unit.unit = parseLengthUnit (options.units);
    unit.reason = "given: --units " + options.units;
  }
  const auto to_mm = static_cast<float> (millimetresPer (unit.unit));
  if (to_mm != 1.0f) {
    for (auto& point : scan)
      point.getVector3fMap () *= to_mm;
    out << "units: the scan's unit is " << toString (unit.unit) << " (" << unit.reason << "); rescaled to mm\n";
  }
  return unit;
}

/** The plausibility checks of the finished fit (the model and the scan in mm). */
FitPlausibility
checkFit (Icp& icp, const MorphableModel& model)
{
  const Eigen::VectorXd sigma = model.variances (icp.getComponentSelection ()).cwiseSqrt ();
  const Eigen::VectorXd in_sigma = icp.getShapeCoefficients ().cwiseQuotient (sigma.cwiseMax (1e-12));
  const Eigen::Matrix3d linear = icp.getFinalTransformation ().topLeftCorner<3, 3> ().cast<double> ();
  return checkFitPlausibility (std::cbrt (linear.determinant ()), icp.getFittedVertices (), icp.getVertexResiduals (),
                               in_sigma, icp.getRegistrationReport ());
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
  for (auto it = landmarks.begin (); it != landmarks.end ();)
    if (model.landmarks ().count (it->first)) {
      ++it;
    }
    else {
      skipped += " " + it->first;
      it = landmarks.erase (it);
    }
  if (!skipped.empty () && !options.quiet)
    warnings << options.landmarks << ": the model has no landmark" << skipped << "; using the other "
             << landmarks.size () << '\n';
  if (landmarks.empty ())
    throw InvalidInputError (options.landmarks + ": none of its landmarks is on the model " + options.model);
  return landmarks;
}

void
configureIcp (Icp& icp, const RegisterOptions& options, const MorphableModel::Ptr& model)
{
  icp.setModel (model);
  icp.setComponentSelection (options.components.size () == 1 ? model->firstComponents (options.components.front ())
                                                             : model->firstComponents (options.components));
  icp.setMaximumIterations (options.iterations);
  icp.setSimilarityIterations (options.similarity_iterations);
  if (options.max_distance > 0.0)
    icp.setMaxCorrespondenceDistance (options.max_distance);
  icp.setPointToPlane (options.point_to_plane, options.tangential_weight);
  icp.setShapePriorWeight (options.shape_prior);
  icp.setAreaWeighting (options.area_weighting);
  icp.setRobustLoss (robustLoss (options.loss), options.loss_scale);
  icp.setTargetSmoothing (options.target_smoothing);
  icp.setTargetUnit (LengthUnit::millimetre); // the scan is converted on loading
  // A chain replaces the default one (the target boundary rejector): it stays first.
  icp.addCorrespondenceRejector (icp.getTargetBoundaryRejector ());
  if (options.reject_distance > 0.0) {
    auto rejector = std::make_shared<pcl::registration::CorrespondenceRejectorDistance> ();
    rejector->setMaximumDistance (static_cast<float> (options.reject_distance));
    icp.addCorrespondenceRejector (rejector);
  }
  if (options.reject_median > 0.0) {
    auto rejector = std::make_shared<pcl::registration::CorrespondenceRejectorMedianDistance> ();
    rejector->setMedianFactor (options.reject_median);
    icp.addCorrespondenceRejector (rejector);
  }
  if (options.reject_one_to_one)
    icp.addCorrespondenceRejector (std::make_shared<pcl::registration::CorrespondenceRejectorOneToOne> ());
  if (options.reject_trimmed > 0.0) {
    auto rejector = std::make_shared<pcl::registration::CorrespondenceRejectorTrimmed> ();
    rejector->setOverlapRatio (static_cast<float> (options.reject_trimmed));
    icp.addCorrespondenceRejector (rejector);
  }
}

/** Prints one progress line per iteration: the kept correspondences and their RMS distance. */
void
showIterations (Icp& icp, const Progress& progress)
{
  auto iteration = std::make_shared<int> (0);
  std::function<Icp::UpdateVisualizerCallbackSignature> callback = [&progress, iteration] (
                                                                       const pcl::PointCloud<pcl::PointNormal>& source,
                                                                       const pcl::Indices& source_indices,
                                                                       const pcl::PointCloud<pcl::PointNormal>& target,
                                                                       const pcl::Indices& target_indices) {
    if (source_indices.empty ())
      return; // PCL's registerVisualizationCallback calls once at registration, before any iteration
    double squares = 0.0;
    for (std::size_t k = 0; k < source_indices.size (); ++k)
      squares +=
          (source[source_indices[k]].getVector3fMap () - target[target_indices[k]].getVector3fMap ()).squaredNorm ();
    std::ostringstream detail;
    detail << ' ' << source_indices.size () << " correspondences, RMS " << std::fixed << std::setprecision (3)
           << std::sqrt (squares / std::max<std::size_t> (source_indices.size (), 1)) << " mm";
    progress.step (++*iteration, detail.str ());
  };
  icp.registerVisualizationCallback (callback);
}

nlohmann::json
similarityJson (const Eigen::Matrix4d& transform)
{
  const Eigen::Matrix3d linear = transform.topLeftCorner<3, 3> ();
  const double scale = std::cbrt (linear.determinant ());
  const Eigen::Matrix4d rows = transform.transpose (); // row-major order in the file
  const Eigen::Matrix3d rotation_rows = (linear / scale).transpose ();
  return {{"matrix_row_major", std::vector<double> (rows.data (), rows.data () + 16)},
          {"scale", scale},
          {"rotation_row_major", std::vector<double> (rotation_rows.data (), rotation_rows.data () + 9)},
          {"translation", {transform (0, 3), transform (1, 3), transform (2, 3)}}};
}

nlohmann::json
iterationsJson (const IcpReport& report)
{
  nlohmann::json history = nlohmann::json::array ();
  for (const IcpIteration& it : report.history)
    history.push_back ({{"stage", toString (it.stage)},
                        {"mean_squared_error_mm2", it.error},
                        {"correspondences", it.correspondences},
                        {"kept", it.kept},
                        {"seconds", it.seconds}});
  return {{"similarity", report.similarity_iterations},
          {"shape", report.shape_iterations},
          {"total", report.history.size ()},
          {"history", history}};
}

nlohmann::json
coefficientsJson (const MorphableModel& model, const ComponentSelection& selection, const Eigen::VectorXd& m)
{
  nlohmann::json coefficients;
  for (int j = 0; j < model.numRegions (); ++j) {
    const Eigen::VectorXd part = m.segment (selection.offset (j), selection.count (j));
    coefficients[model.region (j).name] = std::vector<double> (part.data (), part.data () + part.size ());
  }
  return coefficients;
}

nlohmann::json
settingsJson (const RegisterOptions& options)
{
  return {{"iterations", options.iterations},
          {"similarity_iterations", options.similarity_iterations},
          {"max_correspondence_distance_mm", options.max_distance},
          {"components", options.components},
          {"point_to_plane", options.point_to_plane},
          {"tangential_weight", options.tangential_weight},
          {"shape_prior_weight", options.shape_prior},
          {"area_weighting", options.area_weighting},
          {"landmark_weight", options.landmark_weight},
          {"robust_loss", options.loss},
          {"robust_scale_mm", options.loss_scale},
          {"reject_distance_mm", options.reject_distance},
          {"reject_median_factor", options.reject_median},
          {"reject_one_to_one", options.reject_one_to_one},
          {"reject_trimmed_ratio", options.reject_trimmed},
          {"landmarks", options.landmarks},
          {"units", options.units},
          {"target_smoothing", options.target_smoothing}};
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

/** Scan points and the fitted model coloured by residual, seen from the fitted face's front-left. */
void
saveOverlay (RegistrationVisualizer& viewer, const RegisterOptions& options,
             const pcl::PointCloud<pcl::PointNormal>& scan, const TriangleMesh& fitted,
             const Eigen::VectorXd& residuals, double scale, const Eigen::Matrix4d& pose)
{
  viewer.addTargetCloud (scan, "scan", 0, 1.0);
  viewer.addResidualHeatMap (fitted, residuals, scale);
  const Eigen::Matrix3d linear = pose.topLeftCorner<3, 3> ();
  const Eigen::Matrix3d rotation = linear / std::cbrt (linear.determinant ());
  viewer.resetCamera (rotation * Eigen::Vector3d (0.5, 0.15, 1.0).normalized (), rotation * Eigen::Vector3d::UnitY ());
  viewer.saveScreenshot (options.screenshot, options.width, options.height);
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

std::string
reportPath (const RegisterOptions& options)
{
  return options.report.empty () ? std::filesystem::path (options.out).replace_extension (".json").string ()
                                 : options.report;
}

nlohmann::json
registerScanFile (const RegisterOptions& options)
{
  const auto start = Clock::now ();
  OutputFiles outputs ({options.out, reportPath (options), options.screenshot},
                       {options.scan, options.model, options.landmarks, options.truth});
  // Without X the screenshot would fail after the fit: open the offscreen viewer first.
  std::optional<RegistrationVisualizer> viewer;
  if (!options.screenshot.empty ())
    viewer.emplace (RegistrationVisualizer::Display::Offscreen);
  const MorphableModel::Ptr model = loadModel (options.model);
  return keepOnSuccessOrFitFailure (outputs, [&] {
    return registerScan (options, model, viewer ? &*viewer : nullptr, secondsSince (start), std::cout, std::cerr);
  });
}

namespace
{
/** Writes the report of a fit that lost the scan (it passed its checks, so it is a failed fit, not bad input) and
 *  throws FitCheckFailure.
 */
[[noreturn]] void
reportLostFit (const RegisterOptions& options, std::size_t scan_points, const TooFewCorrespondencesError& error)
{
  const std::string report_path = reportPath (options);
  const nlohmann::json report = {{"status", "failed"},
                                 {"checks", {{"passed", false}, {"failures", {error.what ()}}}},
                                 {"scan", {{"file", options.scan}, {"points", scan_points}}},
                                 {"settings", settingsJson (options)},
                                 {"fitted_mesh", nullptr}};
  writeJsonFile (report_path, report);
  throw FitCheckFailure (std::string (error.what ()) + "; no mesh written (see " + report_path + ")");
}

/** The report's description of the scan and how its unit was found. */
nlohmann::json
scanJson (const RegisterOptions& options, std::size_t scan_points, const LengthUnitGuess& unit)
{
  return {{"file", options.scan},          {"points", scan_points},
          {"units", toString (unit.unit)}, {"unit_detection", options.units == "auto" ? "auto" : "given"},
          {"unit_reason", unit.reason},    {"scale_to_mm", millimetresPer (unit.unit)}};
}

/** The report's residual statistics: scan to model over the correspondences, and per model vertex. */
nlohmann::json
residualsJson (const IcpReport& icp_report, const Eigen::VectorXd& residuals, double colour_scale)
{
  return {{"scan_to_model",
           {{"correspondences", icp_report.correspondences},
            {"mean", icp_report.fitness_mean},
            {"median", icp_report.fitness_median},
            {"rms", icp_report.fitness_rms}}},
          {"per_vertex", distanceStatistics (residuals)},
          {"colour_scale_max", colour_scale}};
}

/** The JSON report of a finished fit (without its truth errors, screenshot and timings). */
nlohmann::json
fitReport (const RegisterOptions& options, Icp& icp, const MorphableModel& model, const nlohmann::json& scan,
           double colour_scale)
{
  const IcpReport& icp_report = icp.getRegistrationReport ();
  const FitPlausibility checks = checkFit (icp, model);
  return {{"status", checks.plausible ? "ok" : "failed"},
          {"checks", {{"passed", checks.plausible}, {"failures", checks.failures}}},
          {"units", "mm"},
          {"scan", scan},
          {"initialisation",
           {{"method", icp_report.initialisation},
            {"detail", icp_report.initialisation_detail},
            {"confidence", icp_report.initialisation_confidence},
            {"head_points", icp_report.head_points}}},
          {"model", {{"file", options.model}, {"vertices", model.numVertices ()}, {"regions", model.numRegions ()}}},
          {"settings", settingsJson (options)},
          {"similarity", similarityJson (icp.getFinalTransformation ().cast<double> ())},
          {"initial_similarity", similarityJson (icp_report.initial_transformation)},
          {"coefficients", coefficientsJson (model, icp.getComponentSelection (), icp.getShapeCoefficients ())},
          {"residuals_mm", residualsJson (icp_report, icp.getVertexResiduals (), colour_scale)},
          {"iterations", iterationsJson (icp_report)},
          {"termination", {{"reason", toString (icp_report.termination)}, {"message", icp_report.message}}},
          {"fitted_mesh", options.out}};
}

/** The fit's one-paragraph summary on \a out; throws FitCheckFailure when the report failed its checks. */
void
concludeFit (const RegisterOptions& options, const IcpReport& icp_report, const nlohmann::json& report,
             double fit_seconds, double colour_scale, bool screenshot, std::ostream& out)
{
  const std::string report_path = reportPath (options);
  out << "registered " << options.scan << " in " << icp_report.history.size () << " iterations ("
      << toString (icp_report.termination) << ", " << fit_seconds << " s): scan-to-model RMS " << icp_report.fitness_rms
      << " mm over " << icp_report.correspondences << " correspondences\n"
      << "wrote " << options.out << " (vertex colours: residual, 0-" << colour_scale << " mm), " << report_path
      << (screenshot ? ", " + options.screenshot : std::string ()) << '\n';
  if (report["checks"]["passed"].get<bool> ())
    return;
  std::string reasons;
  for (const nlohmann::json& failure : report["checks"]["failures"])
    reasons += (reasons.empty () ? "" : "; ") + failure.get<std::string> ();
  throw FitCheckFailure (reasons + " (see " + report_path + ")");
}

/** Runs \a icp's fit with progress shown unless quiet; a lost scan is reported and thrown (reportLostFit). */
void
alignScan (Icp& icp, const RegisterOptions& options, std::size_t scan_points)
{
  const Progress progress ("registering " + options.scan, options.iterations, options.quiet);
  if (!options.quiet)
    showIterations (icp, progress);
  pcl::PointCloud<pcl::PointNormal> aligned;
  try {
    icp.align (aligned);
  }
  catch (const TooFewCorrespondencesError& e) {
    reportLostFit (options, scan_points, e);
  }
  catch (const InvalidInputError& e) { // the scan passed the checks before the fit, but the fit cannot use it
    throw InvalidInputError (options.scan + ": cannot be registered: " + e.what ());
  }
  progress.finish (static_cast<int> (icp.getRegistrationReport ().history.size ()));
}
} // namespace

nlohmann::json
registerScan (const RegisterOptions& options, const MorphableModel::Ptr& model, RegistrationVisualizer* viewer,
              double model_seconds, std::ostream& out, std::ostream& warnings, const FitFollowUp& follow_up)
{
  const auto start = Clock::now ();
  const auto scan = loadScan (options.scan);
  const LengthUnitGuess unit = convertScanToMillimetres (*scan, options, *model, out);
  Icp icp;
  configureIcp (icp, options, model);
  if (!options.landmarks.empty ())
    icp.setTargetLandmarks (modelLandmarks (options, *model, *scan, warnings), options.landmark_weight);
  icp.setInputTarget (scan);
  const double load_seconds = model_seconds + secondsSince (start);

  const auto fit_start = Clock::now ();
  alignScan (icp, options, scan->size ());
  const double fit_seconds = secondsSince (fit_start);

  const auto write_start = Clock::now ();
  const TriangleMesh fitted{icp.getFittedVertices (), model->triangles ()};
  const Eigen::VectorXd& residuals = icp.getVertexResiduals ();
  const double scale = colourScale (residuals, options.colour_max);
  const pcl::PolygonMesh coloured = toPolygonMesh (fitted, residualColours (residuals, scale));
  savePolygonMesh (options.out, coloured);
  const double write_seconds = secondsSince (write_start);

  nlohmann::json report = fitReport (options, icp, *model, scanJson (options, scan->size (), unit), scale);
  if (!options.truth.empty ())
    report["truth_vertex_error_mm"] = truthErrors (options, fitted, residuals, out);
  double screenshot_seconds = 0.0;
  if (viewer) {
    const auto shot_start = Clock::now ();
    saveOverlay (*viewer, options, *scan, fitted, residuals, scale, icp.getFinalTransformation ().cast<double> ());
    screenshot_seconds = secondsSince (shot_start);
    report["screenshot"] = {{"file", options.screenshot}, {"width", options.width}, {"height", options.height}};
  }
  if (follow_up)
    follow_up (*scan, fitted, report);
  report["timings_s"] = {{"load", load_seconds},
                         {"fit", fit_seconds},
                         {"write_mesh", write_seconds},
                         {"screenshot", screenshot_seconds},
                         {"total", model_seconds + secondsSince (start)}};
  // Written last and atomically: a report on disk means the scan's outputs are complete (batch resume trusts it).
  writeJsonFile (reportPath (options), report);
  concludeFit (options, icp.getRegistrationReport (), report, fit_seconds, scale, viewer != nullptr, out);
  return report;
}

void
addRegistrationOptions (CLI::App* command, RegisterOptions& options)
{
  command->add_option ("--width", options.width, "screenshot width (pixels)")
      ->check (CLI::Range (16, 8192))
      ->capture_default_str ();
  command->add_option ("--height", options.height, "screenshot height (pixels)")
      ->check (CLI::Range (16, 8192))
      ->capture_default_str ();
  command->add_option ("--iterations", options.iterations, "ICP iterations, similarity and shape stages together")
      ->check (CLI::Range (1, 10000))
      ->capture_default_str ();
  command
      ->add_option ("--similarity-iterations", options.similarity_iterations,
                    "at most this many iterations fit the similarity alone before the shape joins")
      ->check (CLI::Range (1, 10000))
      ->capture_default_str ();
  command->add_option ("--max-distance", options.max_distance, "max correspondence distance (mm, 0 = no limit)")
      ->check (nonNegative ())
      ->capture_default_str ();
  command
      ->add_option ("--components", options.components,
                    "shape components per region: one count for all, or one per region")
      ->check (nonNegative ())
      ->capture_default_str ();
  command->add_flag ("--point-to-plane,!--point-to-point", options.point_to_plane,
                     "point-to-plane residuals along the scan normals (default) or point-to-point");
  command
      ->add_option ("--tangential-weight", options.tangential_weight,
                    "share of the point-to-point term kept along the tangent plane (point-to-plane)")
      ->check (CLI::Range (0.0, 1.0))
      ->capture_default_str ();
  command
      ->add_option ("--shape-prior", options.shape_prior,
                    "weight of the shape prior (coefficients in prior standard deviations)")
      ->check (nonNegative ())
      ->capture_default_str ();
  command->add_option ("--landmark-weight", options.landmark_weight, "one landmark counts as this many correspondences")
      ->check (nonNegative ())
      ->capture_default_str ();
  command->add_flag ("--target-smoothing,!--no-target-smoothing", options.target_smoothing,
                     "fit to each scan point projected onto its neighbours' plane (default; off for sparse or curved "
                     "real scans)");
  command->add_option ("--units", options.units, "the scan's length unit: auto (from its size), mm, cm, m or in")
      ->check (CLI::IsMember ({"auto", "mm", "cm", "m", "in"}))
      ->capture_default_str ();
  command->add_flag ("--area-weighting", options.area_weighting,
                     "weigh model vertices by their surface area (models with uneven vertex density, e.g. ICT)");
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
      ->check (CLI::Range (0.01, 1.0));
}

void
registerRegisterCommand (CLI::App& app)
{
  auto options = std::make_shared<RegisterOptions> ();
  CLI::App* command = app.add_subcommand ("register", "fit a model file to a scan (MorphableICP)");
  auto* scan =
      command->add_option ("-s,--scan", options->scan, "scan (.pcd .ply .obj .stl .off); its unit: see --units");
  command->add_option ("-m,--model", options->model, "model file (.h5, from build-model or statismo)")->required ();
  command->add_option ("-o,--out", options->out, "fitted mesh to write (PLY; vertex colours = residual)")
      ->capture_default_str ();
  command->add_option ("--report", options->report, "JSON report to write (default: the --out path with .json)");
  command->add_option ("--screenshot", options->screenshot,
                       "PNG of the scan and the fit's residual map (needs X: xvfb-run -a)");
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
  addBatchOptions (command, *options, *batch)->excludes (scan);
  command->callback ([options, batch, command, scan] () {
    if (options->scans.empty () && scan->count () == 0)
      throw CLI::RequiredError ("--scan or --scans");
    runRegister (*options, *batch);
  });
}

} // namespace tools
} // namespace morphreg
