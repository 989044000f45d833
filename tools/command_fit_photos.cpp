// SPDX-License-Identifier: BSD-3-Clause
// `morphreg fit-photos`: a head model fitted to an annotated profile photo and frontal photo (docs/method.md,
// "Fitting to two orthogonal photographs"),
// written as PLY (coloured by the frontal photo, or by the error against a known truth) with a JSON report.
#include "commands.h"
#include "mesh_output.h"
#include "option_checks.h"
#include "pipeline.h"
#include "provenance.h"

#include <morphreg/common/distance_statistics.h>
#include <morphreg/common/error.h>
#include <morphreg/photo/two_view_settings.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/io/output_plan.h>
#include <morphreg/io/output_transaction.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/photo/frontal_texture.h>
#include <morphreg/photo/photo_view_io.h>
#include <morphreg/io/rgb_image.h>
#include <morphreg/photo/two_view_fitting.h>
#include <morphreg/common/colour_map.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>

namespace morphreg
{
namespace tools
{
namespace
{
/** Coefficients beyond this many prior standard deviations are warned about (the report counts them). */
constexpr double kCoefficientWarningSigma = 3.0;

struct FitPhotosOptions : TwoViewSettings
{
  std::string profile, frontal, model, photo, truth, report;
  std::string out = "fitted.ply";
  double colour_max = 5.0;
  bool quiet = false;
};

/** A head and the similarity that took it into the photos' normalised frame, as `synth --photos` writes them. */
struct PhotoTruth
{
  TriangleMesh head;
  Eigen::Matrix4d head_to_photo;
};

PhotoTruth
loadPhotoTruth (const std::string& path)
{
  const nlohmann::json document = readJsonFile (path);
  PhotoTruth truth;
  std::string head_file;
  std::vector<double> pose;
  try {
    head_file = document.at ("head").get<std::string> ();
    pose = document.at ("head_to_photo").get<std::vector<double>> ();
  }
  catch (const nlohmann::json::exception& e) {
    throw FormatError (path + ": expected {\"head\": mesh file, \"head_to_photo\": [16 numbers, column-major]} (" +
                       e.what () + ")");
  }
  if (pose.size () != 16)
    throw FormatError (path + ": head_to_photo has " + std::to_string (pose.size ()) + " numbers, not 16");
  truth.head_to_photo = Eigen::Map<const Eigen::Matrix4d> (pose.data ());
  if (!truth.head_to_photo.allFinite () ||
      !(std::abs (truth.head_to_photo.topLeftCorner<3, 3> ().determinant ()) > 0.0))
    throw FormatError (path + ": head_to_photo is not an invertible similarity");
  truth.head = loadTriangleMesh ((std::filesystem::path (path).parent_path () / head_file).string ());
  return truth;
}

/** Vertex errors (mm) of the fit against the true head: the fitted head in the photo frame taken back through the
 *  true similarity; printed and added to \a report. */
Eigen::VectorXd
truthErrors (const std::string& path, const TwoViewFit& fit, nlohmann::json& report)
{
  const PhotoTruth truth = loadPhotoTruth (path);
  requireSameTopology (fit.image_mesh, truth.head, path);
  const Eigen::Affine3d to_photo (truth.head_to_photo);
  const Eigen::Matrix3Xd back = to_photo.inverse () * fit.image_mesh.vertices;
  const Eigen::Matrix3Xd difference = back - truth.head.vertices;
  const Eigen::VectorXd errors = difference.colwise ().norm ().transpose ();
  report["truth_error_mm"] = distanceStatistics (errors);
  report["truth_error_mm"]["width_rms"] = std::sqrt (difference.row (0).squaredNorm () / difference.cols ());
  report["truth_error_mm"]["file"] = path;
  report["truth_scale_ratio"] = fit.scale / std::cbrt (truth.head_to_photo.topLeftCorner<3, 3> ().determinant ());
  std::cout << "vertex RMS against the truth " << path << ": " << std::fixed << std::setprecision (3)
            << report["truth_error_mm"]["rms"].get<double> () << " mm (max "
            << report["truth_error_mm"]["max"].get<double> () << ", width RMS "
            << report["truth_error_mm"]["width_rms"].get<double> () << ")\n"
            << std::defaultfloat;
  return errors;
}

TwoViewFit
fitViews (const FitPhotosOptions& options, const MorphableModel::ConstPtr& model, const ProfileView& profile,
          const std::optional<FrontalView>& frontal)
{
  if (model->profileLine ().empty ())
    throw InvalidInputError (options.model + ": the model has no profile line; build it with `build-model --dir` on "
                                             "the output of synth or demo (their population.json holds it)");
  if (!options.quiet)
    std::cerr << "fitting " << options.model << " to " << options.profile
              << (options.approach == "profile" ? "" : " and " + options.frontal) << " (" << options.approach << ")\n";
  return fitTwoViews (model, profile, frontal ? &*frontal : nullptr, options,
                      options.profile + (options.approach == "profile" ? "" : " and " + options.frontal));
}

/** The report's warnings (implausible coefficients, outline landmarks left out), the latter also on stderr. */
nlohmann::json
fitWarnings (const FitPhotosOptions& options, const TwoViewFit& fit)
{
  nlohmann::json warnings = nlohmann::json::array ();
  if (fit.maxCoefficientSigma () > kCoefficientWarningSigma)
    warnings.push_back ("a shape coefficient is beyond " + std::to_string (kCoefficientWarningSigma) +
                        " standard deviations");
  if (!fit.ignored_landmarks.empty ()) {
    std::string ids;
    for (const std::string& id : fit.ignored_landmarks)
      ids += (ids.empty () ? "" : ", ") + id;
    warnings.push_back ("outline landmarks left out: " + ids);
    std::cerr << "fit-photos: warning: " << options.frontal << ": the outline landmarks " << ids
              << " mark no fixed point of the face and are left out (--contour-weight to use them)\n";
  }
  return warnings;
}

/** The fit's summary line on stdout, and a warning on stderr when a coefficient is implausibly large. */
void
printFitSummary (const FitPhotosOptions& options, const TwoViewFit& fit, bool with_frontal)
{
  std::cout << "fit (" << options.approach
            << (fit.returned == options.approach || fit.returned == "tps_icp" ? std::string ()
                                                                              : ", returned the " + fit.returned +
                                                                                    " fit: no TPS-ICP round "
                                                                                    "lowered the image error")
            << "): " << fit.history.size () << " iterations, profile RMS " << fit.final_residuals.profile_rms
            << " mm over " << fit.final_residuals.profile_correspondences << " profile-line vertices";
  if (with_frontal)
    std::cout << ", landmark RMS " << fit.final_residuals.landmark_rms << " mm";
  std::cout << "; largest coefficient " << fit.maxCoefficientSigma () << " standard deviations\n";
  if (fit.maxCoefficientSigma () > kCoefficientWarningSigma)
    std::cerr << "fit-photos: warning: a shape coefficient is " << fit.maxCoefficientSigma ()
              << " standard deviations from the mean (beyond " << kCoefficientWarningSigma
              << "): the head may be implausible; raise --shape-prior or --smoothness, or fit fewer --components\n";
}

/** Writes the fitted mesh coloured by its error against --truth (with the error as its quality), by the frontal
 *  --photo, or plain; returns what the colours show.
 */
std::string
writeFittedMesh (const FitPhotosOptions& options, const TwoViewFit& fit, const std::optional<FrontalView>& frontal,
                 const std::optional<RgbImage>& photo, nlohmann::json& report)
{
  if (!options.truth.empty ()) {
    const Eigen::VectorXd errors = truthErrors (options.truth, fit, report);
    savePolygonMesh (options.out, toPolygonMesh (fit.model_mesh, residualColours (errors, options.colour_max), errors));
    return "error against the truth, 0-" + nlohmann::json (options.colour_max).dump () + " mm";
  }
  if (photo) {
    const VertexTexture texture = frontalTexture (fit.image_mesh, frontal->normalisation (), *photo);
    report["texture"] = {{"photo", options.photo}, {"visible_vertices", texture.visibleCount ()}};
    savePolygonMesh (options.out, toPolygonMesh (fit.model_mesh, texture.colours));
    return "frontal photo (grey where unseen)";
  }
  saveTriangleMesh (options.out, fit.model_mesh);
  return "none";
}

void
runFitPhotos (const FitPhotosOptions& options)
{
  const auto start = std::chrono::steady_clock::now ();
  OutputPlan plan;
  for (const auto& [input, role] : {std::pair (options.model, "--model"), std::pair (options.profile, "--profile"),
                                    std::pair (options.frontal, "--frontal"), std::pair (options.photo, "--photo"),
                                    std::pair (options.truth, "--truth")})
    plan.addInput (input, role);
  plan.addOutput (options.out, "--out");
  plan.addOptionalOutput (options.report, "--report");
  plan.check ();
  OutputTransaction outputs (plan.outputs ());
  const MorphableModel::ConstPtr model = loadModelFile (options.model, std::cout);
  const ProfileView profile = loadProfileView (options.profile);
  if (options.frontal.empty () && options.approach != "profile")
    throw InvalidInputError ("fit-photos --approach " + options.approach +
                             " needs --frontal (the frontal landmarks); only --approach profile fits without them");
  const std::optional<FrontalView> frontal =
      options.frontal.empty () ? std::nullopt : std::optional<FrontalView> (loadFrontalView (options.frontal));
  if (!options.photo.empty () && !frontal)
    throw InvalidInputError ("fit-photos --photo needs --frontal: the frontal annotation places the photo");
  // Decoded before the fit: a corrupt photo fails at once, not after the work.
  const std::optional<RgbImage> photo =
      options.photo.empty () ? std::nullopt : std::optional<RgbImage> (loadRgbImage (options.photo));
  const TwoViewFit fit = fitViews (options, model, profile, frontal);

  nlohmann::json report = twoViewFitJson (fit);
  report["status"] = "ok";
  report["units"] = "mm (residuals, coefficients_mm; coefficients in prior standard deviations); the similarity maps "
                    "model mm into the normalised photo frame";
  report["inputs"] = {{"model", options.model}, {"profile", options.profile}, {"frontal", options.frontal}};
  report["warnings"] = fitWarnings (options, fit);
  report["settings"] = toJson (static_cast<const TwoViewSettings&> (options));
  printFitSummary (options, fit, frontal.has_value ());
  const std::string colouring = writeFittedMesh (options, fit, frontal, photo, report);
  report["output"] = {{"mesh", options.out}, {"frame", "model, mm"}, {"colours", colouring}};
  report["seconds"] = std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
  if (!options.report.empty ())
    writeReport (options.report, report);
  outputs.commit ();
  std::cout << "wrote " << options.out << " (model frame, mm) "
            << (colouring == "none" ? "(no colours)"
                                    : meshContents (options.out, colouring,
                                                    options.truth.empty () ? "" : "error against the truth in mm"))
            << '\n';
}
} // namespace

void
registerFitPhotosCommand (CLI::App& app)
{
  auto options = std::make_shared<FitPhotosOptions> ();
  CLI::App* command =
      app.add_subcommand ("fit-photos", "fit a head model to a profile silhouette and frontal landmarks (two photos)");
  command->add_option ("--profile", options->profile, "profile annotation (JSON: silhouette, nose tip, pixels)")
      ->required ();
  command->add_option ("--frontal", options->frontal,
                       "frontal annotation (JSON: named landmarks, pixels); needed by --approach joint and tps");
  command->add_option ("-m,--model", options->model, "model file with a profile line and landmarks (HDF5)")
      ->required ();
  command
      ->add_option ("--approach", options->approach,
                    "joint (one Gauss-Newton over both photos), tps (TPS-ICP) or profile (the silhouette alone)")
      ->check (CLI::IsMember ({"joint", "tps", "profile"}))
      ->capture_default_str ();
  command->add_option ("--photo", options->photo, "frontal photo (PNG/JPEG): colour the fitted head from it");
  command->add_option ("--truth", options->truth,
                       "true head and pose (JSON of `synth --photos`): report the fit's error, colour by it");
  command->add_option ("--smoothness", options->smoothness, "lambda_1, the smoothness prior across regions (> 0)")
      ->check (positive ())
      ->capture_default_str ();
  command
      ->add_option ("--shape-prior", options->shape_prior,
                    "lambda_2, the shape prior (coefficients in prior standard deviations, >= 0)")
      ->check (nonNegative ())
      ->capture_default_str ();
  command
      ->add_option ("--components", options->components,
                    "shape components per region: one count for all, or one per region")
      ->check (nonNegative ())
      ->capture_default_str ();
  command
      ->add_option ("--coefficient-limit", options->coefficient_limit,
                    "no shape coefficient beyond this many prior standard deviations (> 0; inf for no limit)")
      ->check (positiveOrInfinite ())
      ->capture_default_str ();
  command->add_option ("--frontal-weight", options->frontal_weight, "weight of each frontal landmark's rows (> 0)")
      ->check (positive ())
      ->capture_default_str ();
  command
      ->add_option ("--contour-weight", options->contour_weight,
                    "weight of the frontal outline landmarks (jaw, chin, neck, head contour; 0 leaves them out)")
      ->check (nonNegative ())
      ->capture_default_str ();
  command
      ->add_option ("--sagittal-weight", options->sagittal_weight,
                    "weight of the rows that keep the profile in the plane X = 0 (0 for a turned or tilted head)")
      ->check (nonNegative ())
      ->capture_default_str ();
  command->add_option ("--colour-max", options->colour_max, "error (mm) at the top of the colour scale with --truth")
      ->check (positive ())
      ->capture_default_str ();
  command
      ->add_option ("-o,--out", options->out,
                    meshOutputHelp ("fitted head to write (model frame, mm); with --truth or --photo",
                                    "error against the truth, or the frontal photo", "with --truth, the error in mm"))
      ->capture_default_str ();
  command->add_option ("--report", options->report, "JSON report to write");
  command->add_flag ("-q,--quiet", options->quiet, "less output");
  command->callback ([options] () { runFitPhotos (*options); });
}

} // namespace tools
} // namespace morphreg
