// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/photo/photo_fit_options.h>

#include <nlohmann/json.hpp>

namespace morphreg
{
namespace
{
PhotoFitting
configuredFitting (const MorphableModel::ConstPtr& model, const PhotoFitOptions& options)
{
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
