// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/photo/photo_fit_method.h>
#include <morphreg/photo/photo_fit_options.h>

#include <nlohmann/json.hpp>

namespace morphreg
{
namespace
{
using O = PhotoFitOptions;

/** How the photos are fitted: the method, the components and the priors. */
std::vector<PhotoFitOption>
methodOptions ()
{
  std::string methods;
  for (const std::string& name : photoFitMethodNames ())
    methods += (methods.empty () ? "" : ", ") + name;
  return {
      {"approach", "the fitting method: " + methods, &O::approach, 0, 0, photoFitMethodNames ()},
      {"components", "shape components per region: one count for all, or one per region", &O::components, 0, 10000, {}},
      {"smoothness",
       "lambda_1, the smoothness prior across regions (> 0)",
       &O::smoothness,
       kAboveZeroSetting,
       kUnboundedSetting,
       {}},
      {"shape_prior",
       "lambda_2, the shape prior (>= 0, coefficients in prior standard deviations); unset (auto on the command line, "
       "None in Python): chosen from the landmark noise and landmarks left out of the fit",
       &O::shape_prior,
       0,
       kUnboundedSetting,
       {}},
      {"landmark_noise",
       "the landmarks' noise in pixels (> 0)",
       &O::landmark_noise,
       kAboveZeroSetting,
       kUnboundedSetting,
       {}},
      {"coefficient_limit",
       "no shape coefficient beyond this many prior standard deviations (> 0; inf for no limit)",
       &O::coefficient_limit,
       kAboveZeroSetting,
       kInfiniteSetting,
       {}},
  };
}

/** The weights of the landmarks and of the profile's rows. */
std::vector<PhotoFitOption>
weightOptions ()
{
  return {
      {"landmark_weight",
       "weight of each landmark's rows (> 0)",
       &O::landmark_weight,
       kAboveZeroSetting,
       kUnboundedSetting,
       {}},
      {"outline_landmarks",
       "the jaw, chin, neck and head-contour landmarks: outline (the model's outline passes through them), vertex "
       "(fixed vertices) or ignored",
       &O::outline_landmarks,
       0,
       0,
       {"outline", "vertex", "ignored"}},
      {"outline_landmark_weight",
       "weight of each outline landmark's row (>= 0)",
       &O::outline_landmark_weight,
       0,
       kUnboundedSetting,
       {}},
      {"sagittal_weight",
       "weight of the rows that keep the profile in the plane X = 0 (0 for a turned or tilted head)",
       &O::sagittal_weight,
       0,
       kUnboundedSetting,
       {}},
  };
}

PhotoFitting
configuredFitting (const MorphableModel::ConstPtr& model, const PhotoFitOptions& options)
{
  requireValidPhotoFitOptions (options);
  PhotoFitting fitting (model);
  const std::vector<int>& counts = options.components;
  if (counts.empty ())
    throw InvalidInputError ("photo fit setting components is empty: give one count, or one per region");
  fitting.setComponentSelection (counts.size () == 1 ? model->firstComponents (counts.front ())
                                                     : model->firstComponents (counts));
  fitting.setSmoothnessWeight (options.smoothness);
  fitting.setLandmarkNoise (options.landmark_noise);
  if (options.shape_prior)
    fitting.setShapePriorWeight (*options.shape_prior);
  fitting.setCoefficientLimit (options.coefficient_limit);
  fitting.setLandmarkWeight (options.landmark_weight);
  fitting.setOutlineLandmarks (outlineLandmarkMode (options.outline_landmarks), options.outline_landmark_weight);
  fitting.setSagittalWeight (options.sagittal_weight);
  return fitting;
}
} // namespace

const std::vector<PhotoFitOption>&
photoFitOptionTable ()
{
  static const std::vector<PhotoFitOption> options = joinedOptions ({methodOptions (), weightOptions ()});
  return options;
}

void
requireValidPhotoFitOptions (const PhotoFitOptions& options)
{
  requireValidOptions (photoFitOptionTable (), options, "photo fit setting");
}

OutlineLandmarkMode
outlineLandmarkMode (const std::string& name)
{
  if (name == "outline")
    return OutlineLandmarkMode::outline;
  if (name == "vertex")
    return OutlineLandmarkMode::vertex;
  if (name == "ignored")
    return OutlineLandmarkMode::ignored;
  throw InvalidInputError ("outline landmark mode \"" + name + "\" is none of outline, vertex, ignored");
}

PhotoFit
fitPhotos (const MorphableModel::ConstPtr& model, std::vector<PhotoView> views, const PhotoFitOptions& options,
           const std::string& sources)
{
  const PhotoFitMethod::ConstPtr method = photoFitMethod (options.approach);
  const PhotoFitting fitting = configuredFitting (model, options);
  try {
    return fitting.fit (std::move (views), *method);
  }
  catch (const InvalidInputError& e) { // the annotations were read, but the model cannot be fitted to them
    throw InvalidInputError (sources + ": " + e.what ());
  }
}

nlohmann::json
toJson (const PhotoFitOptions& options)
{
  return {{"approach", options.approach},
          {"components", options.components},
          {"lambda1", options.smoothness},
          {"lambda2", options.shape_prior ? nlohmann::json (*options.shape_prior) : nlohmann::json ("from the data")},
          {"landmark_noise_px", options.landmark_noise},
          {"coefficient_limit_sigma", options.coefficient_limit},
          {"landmark_weight", options.landmark_weight},
          {"outline_landmarks", options.outline_landmarks},
          {"outline_landmark_weight", options.outline_landmark_weight},
          {"sagittal_weight", options.sagittal_weight}};
}
} // namespace morphreg
