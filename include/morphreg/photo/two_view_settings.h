// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file two_view_settings.h
 *  \brief The settings of a fit to two photographs by their command-line names (`morphreg fit-photos
 *  --approach ...`), applied in one place for the command line and the Python module.
 */
#include <morphreg/photo/frontal_view.h>
#include <morphreg/photo/profile_view.h>
#include <morphreg/photo/two_view_fit.h>
#include <morphreg/photo/two_view_fitting.h>

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace morphreg
{
/** \brief TwoViewFitting's settings as `morphreg fit-photos` names them (each field is the option without "--", with
 *  '_' for '-'); the defaults are TwoViewFitting's. */
struct TwoViewSettings
{
  std::string approach = "joint"; ///< profile (the silhouette alone), joint (approach 1) or tps (approach 2)
  std::vector<int> components{TwoViewFitting::kDefaultComponents};     ///< per region: one count, or one each
  double smoothness = TwoViewFitting::kDefaultSmoothnessWeight;        ///< lambda_1 (> 0)
  double shape_prior = TwoViewFitting::kDefaultShapePriorWeight;       ///< lambda_2 (>= 0)
  double coefficient_limit = TwoViewFitting::kDefaultCoefficientLimit; ///< coefficient clamp (sigmas, > 0)
  double frontal_weight = TwoViewFitting::kDefaultFrontalWeight;       ///< weight of each frontal landmark (> 0)
  double contour_weight = 0.0;                                         ///< outline landmarks' weight (0 = left out)
  double sagittal_weight = TwoViewFitting::kDefaultSagittalWeight;     ///< weight of the sagittal rows (>= 0)
};

/** \brief Fits \a model to the \a profile view and, unless the approach is "profile", the \a frontal view, with
 *  \a settings. Throws InvalidInputError for an unknown approach, a missing frontal view, a model without a profile
 *  line (TwoViewFitting's), settings out of range, or annotations the model cannot be fitted to (naming \a sources, the annotation files).
 *  \param[in] model the model (with a profile line and landmarks)
 *  \param[in] profile the profile view
 *  \param[in] frontal the frontal view, or nullptr (approach "profile" only)
 *  \param[in] settings the settings
 *  \param[in] sources the annotations' names for messages
 *  \return the fit
 */
TwoViewFit
fitTwoViews (const MorphableModel::ConstPtr& model, const ProfileView& profile, const FrontalView* frontal,
             const TwoViewSettings& settings, const std::string& sources);

/** \brief The settings as the JSON object of fit-photos reports ("lambda1", "lambda2", ...).
 *  \param[in] settings the settings
 *  \return the JSON object
 */
nlohmann::json
toJson (const TwoViewSettings& settings);

} // namespace morphreg
