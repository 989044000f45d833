// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/colour_map.h>
#include <morphreg/common/distance_statistics.h>
#include <morphreg/common/error.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/io/rgb_image_io.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/pipeline/photo_registration.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <utility>

namespace morphreg
{
namespace
{
std::string
pixelSize (int width, int height)
{
  return std::to_string (width) + " x " + std::to_string (height) + " px";
}

/** The orthographic pair of \a files, with the frontal photo's pixels for its view. */
PhotoSet
readPhotoPair (const PhotoSetFiles& files)
{
  const ProfileView profile = loadProfileView (files.profile);
  const std::optional<FrontalView> frontal =
      files.frontal.empty () ? std::nullopt : std::optional<FrontalView> (loadFrontalView (files.frontal));
  if (!files.photo.empty () && !frontal)
    throw InvalidInputError (files.photo + ": a frontal photo needs its frontal annotation, which places it");
  PhotoSet photos{orthographicPairViews (profile, frontal ? &*frontal : nullptr), {}, files.profile};
  photos.images.resize (photos.views.size ());
  if (!frontal)
    return photos;
  photos.sources += " and " + files.frontal;
  if (files.photo.empty ())
    return photos;
  RgbImage& image = photos.images.back ();
  image = loadRgbImage (files.photo);
  const PhotoNormalisation& annotated = frontal->normalisation ();
  if (image.width != annotated.width () || image.height != annotated.height ())
    throw InvalidInputError (files.photo + " is " + pixelSize (image.width, image.height) + ", but " + files.frontal +
                             " annotates a " + pixelSize (annotated.width (), annotated.height ()) + " photo");
  return photos;
}
} // namespace

PhotoSet
readPhotoSet (const PhotoSetFiles& files)
{
  const bool pair = !files.profile.empty () || !files.frontal.empty () || !files.photo.empty ();
  if (!files.views.empty () && pair)
    throw InvalidInputError ("photo views and the orthographic pair (profile, frontal, photo) cannot be fitted "
                             "together (their frames differ)");
  if (files.views.empty () && files.profile.empty ())
    throw InvalidInputError ("no photos: give views (each with landmarks, a camera or an outline) or the "
                             "orthographic pair (a profile and optionally a frontal annotation)");
  if (files.views.empty ())
    return readPhotoPair (files);
  PhotoSet photos;
  for (const PhotoViewFiles& view_files : files.views) {
    LoadedPhotoView loaded = loadPhotoView (view_files);
    photos.views.push_back (std::move (loaded.view));
    photos.images.push_back (std::move (loaded.image));
    photos.sources += (photos.sources.empty () ? "" : ", ") + view_files.image;
  }
  return photos;
}

PhotoTruth
readPhotoTruth (const std::string& path)
{
  const nlohmann::json document = readJsonFile (path);
  PhotoTruth truth;
  truth.source = path;
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

PhotoTruthErrors
photoTruthErrors (const PhotoTruth& truth, const PhotoFit& fit)
{
  requireSameTopology (fit.image_mesh, truth.head, truth.source);
  const Eigen::Affine3d to_photo (truth.head_to_photo);
  const Eigen::Matrix3Xd back = to_photo.inverse () * fit.image_mesh.vertices;
  const Eigen::Matrix3Xd difference = back - truth.head.vertices;
  PhotoTruthErrors errors;
  errors.vertex_errors = difference.colwise ().norm ().transpose ();
  nlohmann::json& statistics = errors.json["truth_error_mm"] = distanceStatistics (errors.vertex_errors);
  statistics["width_rms"] = std::sqrt (difference.row (0).squaredNorm () / difference.cols ());
  statistics["file"] = truth.source;
  errors.json["truth_scale_ratio"] = fit.scale / std::cbrt (truth.head_to_photo.topLeftCorner<3, 3> ().determinant ());
  return errors;
}

std::optional<VertexTexture>
photoTexture (const PhotoFit& fit, const PhotoSet& photos)
{
  std::vector<TexturePhoto> textured;
  for (std::size_t v = 0; v < photos.images.size (); ++v)
    if (photos.images[v].width > 0)
      textured.push_back ({fit.views[v].camera, &photos.images[v]});
  if (textured.empty ())
    return std::nullopt;
  return blendedTexture (fit.image_mesh, textured);
}

PhotoRegistration::PhotoRegistration (MorphableModel::ConstPtr model, std::string model_name, PhotoFitOptions settings)
  : model_ (std::move (model)), model_name_ (std::move (model_name)), settings_ (std::move (settings))
{
  if (!model_)
    throw InvalidInputError ("photo registration: no model given");
}

std::vector<std::string>
PhotoRegistration::fitWarnings (const PhotoFit& fit) const
{
  std::vector<std::string> warnings;
  if (fit.maxCoefficientSigma () > kCoefficientWarningSigma)
    warnings.push_back ("a shape coefficient is beyond " + std::to_string (kCoefficientWarningSigma) +
                        " standard deviations");
  if (!fit.ignored_landmarks.empty ()) {
    std::string ids;
    for (const std::string& id : fit.ignored_landmarks)
      ids += (ids.empty () ? "" : ", ") + id;
    warnings.push_back ("outline landmarks left out: " + ids);
    if (observer_)
      observer_->warning ("the outline landmarks " + ids + " are left out");
  }
  if (!fit.prior.beats_mean_head) {
    warnings.push_back ("the photos predict left-out landmarks no better than the mean head: the fit stays near it");
    if (observer_)
      observer_->warning ("the photos predict left-out landmarks no better than the mean head (" +
                          nlohmann::json (fit.prior.mean_head_error_mm).dump () +
                          " mm): the fit stays near the mean head (lambda_2 " +
                          nlohmann::json (fit.prior.weight).dump () + ")");
  }
  return warnings;
}

std::string
writePhotoFitMesh (const std::string& path, const PhotoFit& fit, const PhotoSet& photos, const std::string& truth_file,
                   double colour_max, nlohmann::json& report)
{
  if (!truth_file.empty ()) {
    const PhotoTruthErrors errors = photoTruthErrors (readPhotoTruth (truth_file), fit);
    report.update (errors.json);
    savePolygonMesh (
        path, toPolygonMesh (fit.model_mesh, residualColours (errors.vertex_errors, colour_max), errors.vertex_errors));
    return "error against the truth, 0-" + nlohmann::json (colour_max).dump () + " mm";
  }
  const std::optional<VertexTexture> texture = photoTexture (fit, photos);
  if (!texture) {
    saveTriangleMesh (path, fit.model_mesh);
    return "none";
  }
  report["texture"] = {{"photos", std::count_if (photos.images.begin (), photos.images.end (),
                                                 [] (const RgbImage& image) { return image.width > 0; })},
                       {"visible_vertices", texture->visibleCount ()}};
  savePolygonMesh (path, toPolygonMesh (fit.model_mesh, texture->colours));
  return "the photos, blended by angle (grey where unseen)";
}

PhotoRegistrationOutcome
PhotoRegistration::fit (const PhotoSet& photos) const
{
  if (model_->profileLine ().empty ())
    throw InvalidInputError (model_name_ + ": the model has no profile line (models built from the populations "
                                           "that synth and demo write hold one)");
  if (observer_)
    observer_->fitStarted (model_name_, photos.sources, settings_.approach);
  PhotoRegistrationOutcome outcome;
  outcome.fit = fitPhotos (model_, photos.views, settings_, photos.sources);
  outcome.warnings = fitWarnings (outcome.fit);
  outcome.report = photoFitJson (outcome.fit);
  outcome.report["status"] = "ok";
  outcome.report["units"] = "mm (residuals, coefficients_mm; coefficients in prior standard deviations); the "
                            "similarity maps model mm into the views' frame";
  outcome.report["inputs"] = {{"model", model_name_}, {"photos", photos.sources}};
  outcome.report["warnings"] = outcome.warnings;
  outcome.report["settings"] = toJson (settings_);
  return outcome;
}
} // namespace morphreg
