// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/photo/photo_fitting.h>
#include <morphreg/photo/shape_prior_selection.h>

#include <cmath>

namespace morphreg
{
namespace
{
/** \a value if it is finite and > 0 (>= 0 with \a zero_allowed); else InvalidInputError naming \a what. */
double
checkedSetting (double value, bool zero_allowed, const std::string& what)
{
  if (!std::isfinite (value) || value < 0.0 || (value == 0.0 && !zero_allowed))
    throw InvalidInputError ("PhotoFitting: " + what + " must be finite and " + (zero_allowed ? ">= 0" : "> 0") +
                             ", got " + std::to_string (value));
  return value;
}

} // namespace

PhotoFitting::PhotoFitting (MorphableModel::ConstPtr model) : model_ (std::move (model))
{
  MultiViewProblem::requireFittable (model_);
  settings_.shape.components = model_->firstComponents (kDefaultComponents);
  settings_.shape.smoothness_weight = kDefaultSmoothnessWeight;
  settings_.shape.coefficient_limit = kDefaultCoefficientLimit;
  settings_.landmark_weight = kDefaultLandmarkWeight;
  settings_.outline_landmark_weight = kDefaultLandmarkWeight;
  settings_.sagittal_weight = kDefaultSagittalWeight;
}

void
PhotoFitting::setComponentSelection (const ComponentSelection& selection)
{
  model_->requireCompatible (selection, nullptr, "PhotoFitting::setComponentSelection");
  settings_.shape.components = selection;
}

void
PhotoFitting::setSmoothnessWeight (double lambda1)
{
  settings_.shape.smoothness_weight =
      checkedSetting (lambda1, false, "lambda_1 (the smoothness weight; regions without data need it)");
}

void
PhotoFitting::setShapePriorWeight (double lambda2, ShapePrior prior)
{
  fixed_prior_ = requirePriorWeight (lambda2, "PhotoFitting: lambda_2");
  settings_.shape.prior = prior;
}

void
PhotoFitting::setLandmarkNoise (double pixels)
{
  landmark_noise_ = checkedSetting (pixels, false, "the landmark noise (pixels)");
  fixed_prior_.reset ();
}

void
PhotoFitting::setCoefficientLimit (double sigmas)
{
  if (!(sigmas > 0.0)) // NaN included; infinity is no limit
    throw InvalidInputError ("PhotoFitting: the coefficient limit must be > 0 standard deviations (infinity for "
                             "none), got " +
                             std::to_string (sigmas));
  settings_.shape.coefficient_limit = sigmas;
}

void
PhotoFitting::setLandmarkWeight (double weight)
{
  settings_.landmark_weight = checkedSetting (weight, false, "the landmark weight");
}

void
PhotoFitting::setOutlineLandmarks (OutlineLandmarkMode mode, double weight)
{
  settings_.outline_landmark_weight = checkedSetting (weight, true, "the outline landmark weight");
  settings_.outline_landmarks = weight == 0.0 ? OutlineLandmarkMode::ignored : mode;
}

void
PhotoFitting::setSagittalWeight (double weight)
{
  settings_.sagittal_weight = checkedSetting (weight, true, "the sagittal weight");
}

void
PhotoFitting::setMaxCorrespondenceDistance (double millimetres)
{
  settings_.max_distance = checkedSetting (millimetres, false, "the max correspondence distance");
}

void
PhotoFitting::setIterations (int similarity, int shape)
{
  if (similarity < 0 || shape < 0)
    throw InvalidInputError ("PhotoFitting: iteration budgets must be >= 0, got " + std::to_string (similarity) +
                             " and " + std::to_string (shape));
  settings_.similarity_iterations = similarity;
  settings_.shape_iterations = shape;
}

PhotoFit
PhotoFitting::fit (std::vector<PhotoView> views, const PhotoFitMethod& method) const
{
  MultiViewProblem problem (model_, std::move (views), settings_);
  problem.estimateCameras ();
  ShapePriorChoice prior;
  if (fixed_prior_) {
    prior.weight = *fixed_prior_;
    prior.rule = "given";
    problem.setPriorWeight (prior.weight);
  }
  else
    prior = ShapePriorSelection (landmark_noise_).choose (problem, method.rows ());
  PhotoFit fit = method.fit (problem, problem.initialState ());
  fit.method = method.name ();
  fit.prior = prior;
  return fit;
}

PhotoFit
PhotoFitting::fit (std::vector<PhotoView> views, const std::string& method) const
{
  return fit (std::move (views), *photoFitMethod (method));
}

PhotoFit
PhotoFitting::fitProfile (const ProfileView& profile, const FrontalView* frontal) const
{
  return fit (orthographicPairViews (profile, frontal), "profile");
}

PhotoFit
PhotoFitting::fitJoint (const ProfileView& profile, const FrontalView& frontal) const
{
  return fit (orthographicPairViews (profile, &frontal), "joint");
}

PhotoFit
PhotoFitting::fitTpsIcp (const ProfileView& profile, const FrontalView& frontal) const
{
  return fit (orthographicPairViews (profile, &frontal), "tps");
}
} // namespace morphreg
