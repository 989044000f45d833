// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/photo/two_view_settings.h>

#include <nlohmann/json.hpp>

namespace morphreg
{
namespace
{
TwoViewFitting
configuredFitting (const MorphableModel::ConstPtr& model, const TwoViewSettings& settings)
{
  TwoViewFitting fitting (model);
  const std::vector<int>& counts = settings.components;
  if (counts.empty ())
    throw InvalidInputError ("fit-photos setting components is empty: give one count, or one per region");
  fitting.setComponentSelection (counts.size () == 1 ? model->firstComponents (counts.front ())
                                                     : model->firstComponents (counts));
  fitting.setSmoothnessWeight (settings.smoothness);
  fitting.setShapePriorWeight (settings.shape_prior);
  fitting.setCoefficientLimit (settings.coefficient_limit);
  fitting.setFrontalWeight (settings.frontal_weight);
  fitting.setContourLandmarkWeight (settings.contour_weight);
  fitting.setSagittalWeight (settings.sagittal_weight);
  return fitting;
}
} // namespace

TwoViewFit
fitTwoViews (const MorphableModel::ConstPtr& model, const ProfileView& profile, const FrontalView* frontal,
             const TwoViewSettings& settings, const std::string& sources)
{
  const std::string& approach = settings.approach;
  if (approach != "profile" && approach != "joint" && approach != "tps")
    throw InvalidInputError ("fit-photos approach \"" + approach + "\" is none of profile, joint, tps");
  if (!frontal && approach != "profile")
    throw InvalidInputError ("fit-photos approach " + approach +
                             " needs the frontal landmarks; only the approach profile fits without them");
  const TwoViewFitting fitting = configuredFitting (model, settings);
  try {
    if (approach == "profile")
      return fitting.fitProfile (profile);
    if (approach == "tps")
      return fitting.fitTpsIcp (profile, *frontal);
    return fitting.fitJoint (profile, *frontal);
  }
  catch (const InvalidInputError& e) { // the annotations were read, but the model cannot be fitted to them
    throw InvalidInputError ("fit-photos: " + sources + ": " + e.what ());
  }
}

nlohmann::json
toJson (const TwoViewSettings& settings)
{
  return {{"approach", settings.approach},
          {"components", settings.components},
          {"lambda1", settings.smoothness},
          {"lambda2", settings.shape_prior},
          {"coefficient_limit_sigma", settings.coefficient_limit},
          {"frontal_weight", settings.frontal_weight},
          {"contour_weight", settings.contour_weight},
          {"sagittal_weight", settings.sagittal_weight}};
}

} // namespace morphreg
