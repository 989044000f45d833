// SPDX-License-Identifier: BSD-3-Clause
// `morphreg fit-photos`: a head model fitted to photos (docs/method.md, "Fitting to photographs"): any number of
// `--view` photos with their landmarks, cameras and outlines, or the orthographic `--profile` and `--frontal` pair;
// written as PLY (coloured by the photos, or by the error against a known truth) with a JSON report.
#include "commands.h"
#include "mesh_output.h"
#include "option_checks.h"
#include "pipeline.h"
#include "provenance.h"

#include <morphreg/common/colour_map.h>
#include <morphreg/common/distance_statistics.h>
#include <morphreg/common/error.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/io/output_plan.h>
#include <morphreg/io/output_transaction.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/photo/photo_fit_options.h>
#include <morphreg/photo/photo_texture.h>
#include <morphreg/photo/photo_view_io.h>
#include <morphreg/io/rgb_image_io.h>

#include <chrono>
#include <cmath>
#include <algorithm>
#include <filesystem>
#include <functional>
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

struct FitPhotosOptions : PhotoFitOptions
{
  std::string profile, frontal, model, photo, truth, report, shape_prior_text = "auto";
  std::vector<PhotoViewFiles> views; ///< --view groups, in order
  std::string out = "fitted.ply";
  double colour_max = 5.0;
  bool quiet = false;
};

/** The photos to fit: the --view photos with their images, or the orthographic pair (and the --photo image). */
struct Photos
{
  std::vector<PhotoView> views;
  std::vector<RgbImage> images; ///< per view (empty image: none to colour from)
  std::string sources;          ///< the inputs' names, for messages
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
truthErrors (const std::string& path, const PhotoFit& fit, nlohmann::json& report)
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

/** The orthographic pair of --profile and --frontal, with the --photo image for the frontal view. */
Photos
pairPhotos (const FitPhotosOptions& options)
{
  const ProfileView profile = loadProfileView (options.profile);
  if (options.frontal.empty () && options.approach != "profile")
    throw InvalidInputError ("fit-photos --approach " + options.approach +
                             " needs --frontal (the frontal landmarks); only --approach profile fits without them");
  const std::optional<FrontalView> frontal =
      options.frontal.empty () ? std::nullopt : std::optional<FrontalView> (loadFrontalView (options.frontal));
  if (!options.photo.empty () && !frontal)
    throw InvalidInputError ("fit-photos --photo needs --frontal: the frontal annotation places the photo");
  Photos photos{orthographicPairViews (profile, frontal ? &*frontal : nullptr), {}, options.profile};
  photos.images.resize (photos.views.size ());
  if (frontal) {
    photos.sources += " and " + options.frontal;
    if (!options.photo.empty ())
      photos.images.back () = loadRgbImage (options.photo);
    if (!options.photo.empty () && (photos.images.back ().width != frontal->normalisation ().width () ||
                                    photos.images.back ().height != frontal->normalisation ().height ()))
      throw InvalidInputError ("fit-photos: " + options.photo + " is " + std::to_string (photos.images.back ().width) +
                               " x " + std::to_string (photos.images.back ().height) + " px, but " + options.frontal +
                               " annotates a " + std::to_string (frontal->normalisation ().width ()) + " x " +
                               std::to_string (frontal->normalisation ().height ()) + " px photo");
  }
  return photos;
}

Photos
loadPhotos (const FitPhotosOptions& options)
{
  if (!options.views.empty () && (!options.profile.empty () || !options.frontal.empty () || !options.photo.empty ()))
    throw InvalidInputError ("fit-photos: --view photos and the orthographic pair (--profile, --frontal, --photo) "
                             "cannot be fitted together (their frames differ)");
  if (options.views.empty () && options.profile.empty ())
    throw InvalidInputError ("fit-photos: give --view photos (with --landmarks, --camera, --outline) or the "
                             "orthographic pair (--profile, --frontal)");
  if (options.views.empty ())
    return pairPhotos (options);
  Photos photos;
  for (const PhotoViewFiles& files : options.views) {
    LoadedPhotoView loaded = loadPhotoView (files);
    photos.views.push_back (std::move (loaded.view));
    photos.images.push_back (std::move (loaded.image));
    photos.sources += (photos.sources.empty () ? "" : ", ") + files.image;
  }
  return photos;
}

PhotoFit
fitViews (const FitPhotosOptions& options, const MorphableModel::ConstPtr& model, const Photos& photos)
{
  if (model->profileLine ().empty ())
    throw InvalidInputError (options.model + ": the model has no profile line; build it with `build-model --dir` on "
                                             "the output of synth or demo (their population.json holds it)");
  if (!options.quiet)
    std::cerr << "fitting " << options.model << " to " << photos.sources << " (" << options.approach << ")\n";
  return fitPhotos (model, photos.views, options, photos.sources);
}

/** The report's warnings (implausible coefficients, landmarks left out, a prior that keeps the mean head), the
 *  latter two also on stderr. */
nlohmann::json
fitWarnings (const PhotoFit& fit)
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
    std::cerr << "fit-photos: warning: the outline landmarks " << ids << " are left out (--outline-landmarks)\n";
  }
  if (!fit.prior.beats_mean_head) {
    warnings.push_back ("the photos predict left-out landmarks no better than the mean head: the fit stays near it");
    std::cerr << "fit-photos: warning: the photos predict left-out landmarks no better than the mean head ("
              << fit.prior.mean_head_error_mm << " mm): the fit stays near the mean head (lambda_2 " << fit.prior.weight
              << ")\n";
  }
  return warnings;
}

/** The fit's summary line on stdout, and a warning on stderr when a coefficient is implausibly large. */
void
printFitSummary (const FitPhotosOptions& options, const PhotoFit& fit)
{
  std::cout << "fit (" << options.approach
            << (fit.returned == options.approach || fit.returned == "tps_icp" ? std::string ()
                                                                              : ", returned the " + fit.returned +
                                                                                    " fit: no TPS-ICP round "
                                                                                    "lowered the image error")
            << "): " << fit.history.size () << " iterations, outline RMS " << fit.final_residuals.outline_rms
            << " mm over " << fit.final_residuals.outline_correspondences << " outline points";
  if (fit.final_residuals.landmark_rms > 0.0)
    std::cout << ", landmark RMS " << fit.final_residuals.landmark_rms << " mm";
  std::cout << "; lambda_2 " << fit.prior.weight << " (" << fit.prior.rule << "); largest coefficient "
            << fit.maxCoefficientSigma () << " standard deviations\n";
  if (fit.maxCoefficientSigma () > kCoefficientWarningSigma)
    std::cerr << "fit-photos: warning: a shape coefficient is " << fit.maxCoefficientSigma ()
              << " standard deviations from the mean (beyond " << kCoefficientWarningSigma
              << "): the head may be implausible; raise --shape-prior or --smoothness, or fit fewer --components\n";
}

/** Writes the fitted mesh coloured by its error against --truth (with the error as its quality), by the photos, or plain; returns what the colours
 *  show. */
std::string
writeFittedMesh (const FitPhotosOptions& options, const PhotoFit& fit, const Photos& photos, nlohmann::json& report)
{
  if (!options.truth.empty ()) {
    const Eigen::VectorXd errors = truthErrors (options.truth, fit, report);
    savePolygonMesh (options.out, toPolygonMesh (fit.model_mesh, residualColours (errors, options.colour_max), errors));
    return "error against the truth, 0-" + nlohmann::json (options.colour_max).dump () + " mm";
  }
  std::vector<TexturePhoto> textured;
  for (size_t v = 0; v < photos.images.size (); ++v)
    if (photos.images[v].width > 0)
      textured.push_back ({fit.views[v].camera, &photos.images[v]});
  if (textured.empty ()) {
    saveTriangleMesh (options.out, fit.model_mesh);
    return "none";
  }
  const VertexTexture texture = blendedTexture (fit.image_mesh, textured);
  report["texture"] = {{"photos", textured.size ()}, {"visible_vertices", texture.visibleCount ()}};
  savePolygonMesh (options.out, toPolygonMesh (fit.model_mesh, texture.colours));
  return "the photos, blended by angle (grey where unseen)";
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
  for (const PhotoViewFiles& view : options.views)
    for (const std::string& input : {view.image, view.landmarks, view.camera, view.outline})
      plan.addInput (input, "--view");
  plan.addOutput (options.out, "--out");
  plan.addOptionalOutput (options.report, "--report");
  plan.check ();
  OutputTransaction outputs (plan.outputs ());
  const MorphableModel::ConstPtr model = loadModelFile (options.model, std::cout);
  const Photos photos = loadPhotos (options);
  const PhotoFit fit = fitViews (options, model, photos);

  nlohmann::json report = photoFitJson (fit);
  report["status"] = "ok";
  report["units"] = "mm (residuals, coefficients_mm; coefficients in prior standard deviations); the similarity maps "
                    "model mm into the views' frame";
  report["inputs"] = {{"model", options.model}, {"photos", photos.sources}};
  report["warnings"] = fitWarnings (fit);
  report["settings"] = toJson (static_cast<const PhotoFitOptions&> (options));
  printFitSummary (options, fit);
  const std::string colouring = writeFittedMesh (options, fit, photos, report);
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

/** Groups the --view, --landmarks, --camera and --outline values in the order given: each of the last three belongs
 *  to the --view before it. */
std::vector<PhotoViewFiles>
viewGroups (const CLI::App& command, const CLI::Option* view, const std::vector<const CLI::Option*>& parts)
{
  std::vector<PhotoViewFiles> groups;
  std::vector<size_t> used (4, 0);
  for (const CLI::Option* option : command.parse_order ()) {
    const auto part = std::find (parts.begin (), parts.end (), option) - parts.begin ();
    if (option != view && part == static_cast<long> (parts.size ()))
      continue;
    const std::string value = option->results ()[used[option == view ? 0 : part + 1]++];
    if (option == view) {
      groups.push_back ({value, "", "", ""});
      continue;
    }
    if (groups.empty ())
      throw InvalidInputError ("fit-photos " + option->get_name () + " " + value +
                               ": give it after the --view photo it belongs to");
    std::string& slot = part == 0   ? groups.back ().landmarks
                        : part == 1 ? groups.back ().camera
                                    : groups.back ().outline;
    if (!slot.empty ())
      throw InvalidInputError ("fit-photos: " + groups.back ().image + " has two " + option->get_name ());
    slot = value;
  }
  return groups;
}

/** Adds --view and the per-view --landmarks, --camera and --outline; returns what groups their values. */
std::function<std::vector<PhotoViewFiles> ()>
addViewOptions (CLI::App* command)
{
  const auto repeatable = [command] (const std::string& name, const std::string& help) {
    return command->add_option (name, help)->expected (1)->multi_option_policy (CLI::MultiOptionPolicy::TakeAll);
  };
  const CLI::Option* view = repeatable ("--view", "a photo (PNG/JPEG) to fit; repeat for more. The --landmarks, "
                                                  "--camera and --outline after it belong to it");
  const std::vector<const CLI::Option*> parts = {
      repeatable ("--landmarks", "the photo's landmarks (.json, .csv or .pts; ids of docs/landmarks.md or iBUG-68)"),
      repeatable ("--camera", "the photo's camera (JSON: K, R, t or P, or a list by image); estimated from the "
                              "landmarks when absent"),
      repeatable ("--outline", "the head's outline traced on the photo (JSON: outline, optional hairline)")};
  return [command, view, parts] () { return viewGroups (*command, view, parts); };
}

void
addFitSettingOptions (CLI::App* command, const std::shared_ptr<FitPhotosOptions>& options)
{
  command->add_option ("--smoothness", options->smoothness, "lambda_1, the smoothness prior across regions (> 0)")
      ->check (positive ())
      ->capture_default_str ();
  command
      ->add_option ("--shape-prior", options->shape_prior_text,
                    "lambda_2, the shape prior (>= 0, coefficients in prior standard deviations), or auto: chosen "
                    "from the landmark noise and landmarks left out of the fit")
      ->check (CLI::IsMember ({"auto"}) | nonNegative ())
      ->capture_default_str ();
  command->add_option ("--landmark-noise", options->landmark_noise, "the landmarks' noise in pixels (> 0)")
      ->check (positive ())
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
  command->add_option ("--landmark-weight", options->landmark_weight, "weight of each landmark's rows (> 0)")
      ->check (positive ())
      ->capture_default_str ();
  command
      ->add_option ("--outline-landmarks", options->outline_landmarks,
                    "the jaw, chin, neck and head-contour landmarks: outline (the model's outline passes through "
                    "them), vertex (fixed vertices) or ignored")
      ->check (CLI::IsMember ({"outline", "vertex", "ignored"}))
      ->capture_default_str ();
  command
      ->add_option ("--outline-landmark-weight", options->outline_landmark_weight,
                    "weight of each outline landmark's row (>= 0)")
      ->check (nonNegative ())
      ->capture_default_str ();
  command
      ->add_option ("--sagittal-weight", options->sagittal_weight,
                    "weight of the rows that keep the profile in the plane X = 0 (0 for a turned or tilted head)")
      ->check (nonNegative ())
      ->capture_default_str ();
}
} // namespace

void
registerFitPhotosCommand (CLI::App& app)
{
  auto options = std::make_shared<FitPhotosOptions> ();
  CLI::App* command = app.add_subcommand (
      "fit-photos", "fit a head model to photos: --view photos with landmarks, or a profile and frontal photo");
  command->add_option ("-m,--model", options->model, "model file with a profile line and landmarks (HDF5)")
      ->required ();
  const auto view_groups = addViewOptions (command);
  command->add_option ("--profile", options->profile, "profile annotation (JSON: silhouette, nose tip, pixels)");
  command->add_option ("--frontal", options->frontal,
                       "frontal annotation (JSON: named landmarks, pixels); needed by --approach joint and tps");
  std::string approaches;
  for (const std::string& name : photoFitMethodNames ())
    approaches += (approaches.empty () ? "" : ", ") + name;
  command->add_option ("--approach", options->approach, "the fitting method: " + approaches)
      ->check (CLI::IsMember (photoFitMethodNames ()))
      ->capture_default_str ();
  command->add_option ("--photo", options->photo, "frontal photo (PNG/JPEG) of --frontal: colour the head from it");
  command->add_option ("--truth", options->truth,
                       "true head and pose (JSON of `synth --photos`): report the fit's error, colour by it");
  addFitSettingOptions (command, options);
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
  command->callback ([options, view_groups] () {
    options->views = view_groups ();
    if (options->shape_prior_text != "auto")
      options->shape_prior = std::stod (options->shape_prior_text);
    runFitPhotos (*options);
  });
}
} // namespace tools
} // namespace morphreg
