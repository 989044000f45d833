// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file photo_fit_options.h
 *  \brief The settings of a photo fit by their command-line names (`morphreg fit-photos --approach ...`), applied in
 *  one place for the command line and the Python module, and their one table (name, help text, range or choices)
 *  that the command line, the Python keywords and the library's checks all read.
 */
#include <morphreg/common/setting_options.h>
#include <morphreg/photo/photo_fit.h>
#include <morphreg/photo/photo_fitting.h>
#include <morphreg/photo/photo_view.h>

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief PhotoFitting's settings as `morphreg fit-photos` names them (each field is the option without "--", with
 *  '_' for '-'); the defaults are PhotoFitting's. */
struct PhotoFitOptions
{
  std::string approach = "joint"; ///< a registered PhotoFitMethod: profile, joint (approach 1) or tps (approach 2)
  std::vector<int> components{PhotoFitting::kDefaultComponents};         ///< per region: one count, or one each
  double smoothness = PhotoFitting::kDefaultSmoothnessWeight;            ///< lambda_1 (> 0)
  std::optional<double> shape_prior;                                     ///< lambda_2 (>= 0); none: from the data
  double landmark_noise = PhotoFitting::kDefaultLandmarkNoise;           ///< pixels (> 0), for the data-chosen prior
  double coefficient_limit = PhotoFitting::kDefaultCoefficientLimit;     ///< coefficient clamp (sigmas, > 0)
  double landmark_weight = PhotoFitting::kDefaultLandmarkWeight;         ///< weight of each landmark (> 0)
  std::string outline_landmarks = "outline";                             ///< outline, vertex or ignored
  double outline_landmark_weight = PhotoFitting::kDefaultLandmarkWeight; ///< their weight (>= 0)
  double sagittal_weight = PhotoFitting::kDefaultSagittalWeight;         ///< weight of the sagittal rows (>= 0)
};

/** \brief One setting of PhotoFitOptions as users set it. */
using PhotoFitOption = SettingOption<PhotoFitOptions>;

/** \brief Every user setting of a photo fit.
 *  \return the table, in the order --help lists it */
const std::vector<PhotoFitOption>&
photoFitOptionTable ();

/** \brief Throws InvalidInputError naming the first setting of \a options ("photo fit setting NAME") outside its
 *  range or choices.
 *  \param[in] options the settings */
void
requireValidPhotoFitOptions (const PhotoFitOptions& options);

/** \brief The mode called \a name ("outline", "vertex", "ignored"); InvalidInputError otherwise.
 *  \param[in] name the mode's name
 *  \return the mode
 */
OutlineLandmarkMode
outlineLandmarkMode (const std::string& name);

/** \brief Fits \a model to \a views with \a options. Throws InvalidInputError for an unknown approach, settings out
 *  of range, or photos the model cannot be fitted to (the message starting with \a sources, the inputs' names).
 *  \param[in] model the model (with a profile line and landmarks)
 *  \param[in] views the photos
 *  \param[in] options the settings
 *  \param[in] sources the inputs' names for messages
 *  \return the fit
 */
PhotoFit
fitPhotos (const MorphableModel::ConstPtr& model, std::vector<PhotoView> views, const PhotoFitOptions& options,
           const std::string& sources);

/** \brief The settings as the JSON object of fit-photos reports ("lambda1", "lambda2", ...).
 *  \param[in] options the settings
 *  \return the JSON object
 */
nlohmann::json
toJson (const PhotoFitOptions& options);
} // namespace morphreg
