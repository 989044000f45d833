// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/model/coefficient_units.h>
#include <morphreg/common/error.h>
#include <morphreg/io/json_file.h>
#include <morphreg/photo/photo_camera_io.h>
#include <morphreg/photo/photo_fit.h>

#include <cmath>

namespace morphreg
{
namespace
{
nlohmann::json
iterationJson (const PhotoFitIteration& iteration)
{
  const char* const stages[] = {"similarity", "shape", "tps_icp"};
  return {{"stage", stages[static_cast<int> (iteration.stage)]},
          {"outline_correspondences", iteration.outline_correspondences},
          {"outline_inside", iteration.outline_inside},
          {"outline_rms_mm", iteration.outline_rms},
          {"landmark_rms_mm", iteration.landmark_rms},
          {"outline_landmarks", iteration.outline_landmarks},
          {"outline_landmark_rms_mm", iteration.outline_landmark_rms}};
}

nlohmann::json
priorJson (const ShapePriorChoice& prior)
{
  nlohmann::json candidates = nlohmann::json::array ();
  for (const PriorCandidate& candidate : prior.candidates)
    candidates.push_back ({{"lambda2", candidate.weight}, {"left_out_error_mm", candidate.error_mm}});
  nlohmann::json json = {{"lambda2", prior.weight},
                         {"noise_lambda2", prior.noise_weight},
                         {"rule", prior.rule},
                         {"candidates", candidates},
                         {"beats_mean_head", prior.beats_mean_head}};
  if (!prior.candidates.empty ())
    json["mean_head_left_out_error_mm"] = prior.mean_head_error_mm;
  return json;
}

nlohmann::json
viewJson (const PhotoFitView& view)
{
  nlohmann::json json = {{"source", view.source},
                         {"camera", photoCameraJson (view.camera)},
                         {"camera_estimated", view.camera_estimated},
                         {"landmarks", view.landmarks},
                         {"outline_landmarks", view.outline_landmarks},
                         {"outline_points", view.outline_points},
                         {"outline_two_sided", view.outline_two_sided},
                         {"hairline", view.hairline}};
  if (view.camera_estimated) {
    json["focal_source"] = view.focal_source;
    json["camera_rms_px"] = view.camera_rms_pixels;
  }
  return json;
}
} // namespace

Eigen::Matrix4d
PhotoFit::similarity () const
{
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity ();
  m.topLeftCorner<3, 3> () = scale * rotation;
  m.topRightCorner<3, 1> () = translation;
  return m;
}

double
PhotoFit::maxCoefficientSigma () const
{
  return coefficients.size () > 0 ? coefficients.cwiseAbs ().maxCoeff () : 0.0;
}

double
PhotoFit::shapeDistance () const
{
  return coefficients.norm ();
}

bool
isPlausibleShape (const Eigen::VectorXd& standardised)
{
  const double p = static_cast<double> (standardised.size ());
  return standardised.squaredNorm () <= p + 5.0 * std::sqrt (2.0 * p);
}

nlohmann::json
photoFitJson (const PhotoFit& fit)
{
  nlohmann::json history = nlohmann::json::array (), views = nlohmann::json::array ();
  for (const PhotoFitIteration& iteration : fit.history)
    history.push_back (iterationJson (iteration));
  for (const PhotoFitView& view : fit.views)
    views.push_back (viewJson (view));
  nlohmann::json rotation = nlohmann::json::array ();
  for (int r = 0; r < 3; ++r)
    rotation.push_back ({fit.rotation (r, 0), fit.rotation (r, 1), fit.rotation (r, 2)});
  return {{"scale", fit.scale},
          {"rotation", rotation},
          {"translation", {fit.translation.x (), fit.translation.y (), fit.translation.z ()}},
          {"component_counts", fit.selection.counts ()},
          {"coefficients",
           std::vector<double> (fit.coefficients.data (), fit.coefficients.data () + fit.coefficients.size ())},
          {"coefficients_unit", kCoefficientsUnit},
          {"coefficients_mm", std::vector<double> (fit.coefficients_mm.data (),
                                                   fit.coefficients_mm.data () + fit.coefficients_mm.size ())},
          {"method", fit.method},
          {"returned", fit.returned},
          {"tps_rounds", fit.tps_rounds},
          {"max_coefficient_sigma", fit.maxCoefficientSigma ()},
          {"coefficients_beyond_3_sigma", (fit.coefficients.array ().abs () > 3.0).count ()},
          {"shape_distance_sigma", fit.shapeDistance ()},
          {"plausible_shape", isPlausibleShape (fit.coefficients)},
          {"prior", priorJson (fit.prior)},
          {"ignored_landmarks", fit.ignored_landmarks},
          {"views", views},
          {"final", iterationJson (fit.final_residuals)},
          {"history", history}};
}

void
savePhotoFitReport (const std::string& path, const PhotoFit& fit)
{
  writeJsonFile (path, photoFitJson (fit));
}
} // namespace morphreg
