// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file fit_plausibility.h
 *  \brief Whether a finished head fit is believable, so that a failed registration is never silent: its size, its
 *  shape, how much of the model the scan supports, how close it lies to the scan, and how it ended.
 */
#include <morphreg/model/morphable_model.h>
#include <morphreg/registration/registration_report.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace morphreg
{
/** \brief Limits of checkFitPlausibility (the fit in mm: the scan converted to mm, the model in mm). */
struct FitPlausibilitySettings
{
  /** \brief Smallest plausible similarity scale. The model's components carry the population's size variation
   *  (adult head lengths vary by about 4 % per standard deviation, so +-8 % covers 95 %); a scale beyond 0.75-1.33
   *  is a head a quarter smaller or a third larger than the model can be, i.e. a wrong unit or the model fitted to
   *  the wrong object. */
  double min_scale = 0.75;
  double max_scale = 1.33;               ///< largest plausible similarity scale (see min_scale)
  double min_correspondence_share = 0.2; ///< share of model vertices with an accepted correspondence
  double max_sigma = 5.0;                ///< no leading shape coefficient beyond this many prior standard deviations
  /** \brief checkRegistration holds each region's first this many components to max_sigma, not the minor ones: a
   *  failed fit shows in the leading components, while a well fitted unseen head may lie further out along the
   *  minor ones, whose variances a population underestimates, and along those the scan barely sees (synthetic scans
   *  fitted with 60 components per region at a weak prior: a chin's 9th component at 5.5 sigma in a fit 0.19 mm
   *  from the truth, mean over its vertices). */
  int leading_components = 5;
  double min_thickness_ratio = 0.25; ///< smallest principal spread of the fitted vertices over the largest
  double max_median_residual = 5.0;  ///< mm: the median scan-to-model distance of the accepted correspondences
};

/** \brief The verdict: plausible, or one sentence with the numbers per failed check. */
struct FitPlausibility
{
  bool plausible = true;             ///< true if every check passed
  std::vector<std::string> failures; ///< one sentence with the numbers per failed check (empty if plausible)
};

/** \brief Checks a finished fit: \a scale (of the similarity), \a fitted_vertices (3 x N, mm), \a vertex_residuals
 *  (per model vertex, NaN without a correspondence), \a coefficients_in_sigma (the shape coefficients divided by
 *  their prior standard deviations) and \a report (the median residual; a divergence other than the cost rising
 *  above its best, which is the normal end of a settled fit). Throws InvalidInputError for mismatched sizes.
 *  \param[in] scale the scale of the fitted similarity (1: the model's own size)
 *  \param[in] fitted_vertices the fitted model vertices (3 x N, mm)
 *  \param[in] vertex_residuals the scan-to-model distance per model vertex (mm; NaN without a correspondence)
 *  \param[in] coefficients_in_sigma the shape coefficients held to max_sigma, divided by their prior standard
 *  deviations
 *  \param[in] report the fit's report: its median residual and how it ended
 *  \param[in] settings the limits of the checks
 *  \return the verdict, with a sentence per failed check
 */
FitPlausibility
checkFitPlausibility (double scale, const Eigen::Matrix3Xd& fitted_vertices, const Eigen::VectorXd& vertex_residuals,
                      const Eigen::VectorXd& coefficients_in_sigma, const IcpReport& report,
                      const FitPlausibilitySettings& settings = FitPlausibilitySettings ());

/** \brief The coefficients of each region's first \a leading components of \a selection (fewer where the region
 *  has fewer), divided by their prior standard deviations: what checkFitPlausibility holds to its sigma limit.
 *  \param[in] model the model fitted
 *  \param[in] selection the components fitted, stacked like \a coefficients
 *  \param[in] coefficients the fitted shape coefficients (mm)
 *  \param[in] leading the components per region kept (FitPlausibilitySettings::leading_components)
 *  \return the kept coefficients in standard deviations, region by region
 */
Eigen::VectorXd
leadingCoefficientsInSigma (const MorphableModel& model, const ComponentSelection& selection,
                            const Eigen::VectorXd& coefficients, int leading);

} // namespace morphreg
