// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file fit_plausibility.h
 *  \brief Whether a finished head fit is believable, so that a failed registration is never silent. A fit is judged
 *  by what it does to the scan (how much of the scan it explains, how much of the model the scan supports, how close
 *  it lies) and by its shape (its size, a collapse, a surface folded over itself, coefficients far outside the
 *  model's population), not by one coefficient: real heads lie well outside a model's population along some
 *  components (the ICT-FaceKit model's noses and mouths fit real scans at 5-7 standard deviations) and still fit.
 */
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/model/morphable_model.h>
#include <morphreg/registration/registration_report.h>

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace morphreg
{
/** \brief Scan points within this distance (mm) of the fitted surface count as explained by the fit. */
constexpr double kExplainedDistance = 5.0;

/** \brief What a finished fit is judged by, measured by measureFit (lengths in mm). */
struct FitMeasures
{
  double scale = 1.0;                ///< the similarity's scale (1: the model's own size)
  double correspondence_share = 1.0; ///< share of the model's vertices with an accepted correspondence
  double largest_sigma = 0.0;        ///< the largest leading shape coefficient, in prior standard deviations
  double thickness_ratio = 1.0;      ///< smallest over largest principal spread of the fitted vertices
  double median_residual = 0.0;      ///< the median scan-to-model distance of the accepted correspondences (mm)
  /** Share of the scan's head points that lie within kExplainedDistance of the fitted surface; 1 when no scan was
   *  measured. The head points are those the fitted surface covers (their closest fitted point is not on its
   *  boundary) within 25 mm of it: farther ones are other things (a wall, a chair, the body, hair spikes). */
  double explained_share = 1.0;
  int scored_points = 0;     ///< the scan's head points scored for explained_share
  double folded_share = 0.0; ///< share of the surface (by the mean's areas) turned over against the mean's
  /** Per model region (its name and share): the share of its own vertices (blending weight >= 0.5) with an
   *  accepted correspondence within kExplainedDistance: what the scan covers of the head (a face-only scan leaves
   *  the back of the head and the neck near 0, where the fit shows the model's prior, not the person). */
  std::vector<std::pair<std::string, double>> region_coverage;
  IcpDivergence divergence = IcpDivergence::none; ///< what diverged, if anything
  std::string divergence_message;                 ///< the divergence's sentence
};

/** \brief Limits of checkFitPlausibility. */
struct FitPlausibilitySettings
{
  /** \brief Smallest plausible similarity scale. The model's components carry the population's size variation
   *  (adult head lengths vary by about 4 % per standard deviation, so +-8 % covers 95 %); a scale beyond 0.75-1.33
   *  is a head a quarter smaller or a third larger than the model can be, i.e. a wrong unit or the model fitted to
   *  the wrong object. */
  double min_scale = 0.75;
  double max_scale = 1.33;                ///< largest plausible similarity scale (see min_scale)
  double min_correspondence_share = 0.15; ///< share of model vertices with an accepted correspondence
  /** \brief No leading shape coefficient beyond this many prior standard deviations: a runaway fit. Real heads
   *  fitted well reach 7 along a model's leading components (ICT-FaceKit's nose and mouth on two of the shared real
   *  scans), so this is no test of a face's shape, only of a fit that left the model. */
  double max_sigma = 10.0;
  /** \brief measureFit holds each region's first this many components to max_sigma, not the minor ones: a failed
   *  fit shows in the leading components, while a well fitted head may lie further out along the minor ones, whose
   *  variances a population underestimates, and along those the scan barely sees. */
  int leading_components = 5;
  double min_thickness_ratio = 0.25; ///< smallest principal spread of the fitted vertices over the largest
  double max_median_residual = 5.0;  ///< mm: the median scan-to-model distance of the accepted correspondences
  /** \brief Share of the covered scan points a fit must explain: a fit onto the wrong object, a collapse onto a few
   *  points or a pose turned away from the head leaves most of the scan unexplained. */
  double min_explained_share = 0.6;
  /** \brief Largest share of the surface (by the mean's triangle areas) turned over against the model mean's: a
   *  surface folded over itself. Well fitted real scans turn 0.02-0.5 % (tiny triangles in the eyes and mouth). */
  double max_folded_share = 0.02;
};

/** \brief The verdict: plausible, or one sentence with the numbers per failed check. */
struct FitPlausibility
{
  bool plausible = true;             ///< true if every check passed
  std::vector<std::string> failures; ///< one sentence with the numbers per failed check (empty if plausible)
};

/** \brief Measures a finished fit (everything in mm). Throws InvalidInputError for mismatched sizes.
 *  \param[in] model the model fitted
 *  \param[in] selection the components fitted, stacked like \a coefficients
 *  \param[in] coefficients the fitted shape coefficients (mm)
 *  \param[in] similarity the fitted model-to-scan similarity
 *  \param[in] fitted_vertices the fitted model vertices (3 x N, scan frame, mm)
 *  \param[in] vertex_residuals the scan-to-model distance per model vertex (mm; NaN without a correspondence)
 *  \param[in] scan the scan points (3 x M, mm); at most 20,000 of them, spread through the scan, are scored; may be
 *  empty (explained_share is then 1)
 *  \param[in] report the fit's report: its median residual and how it ended
 *  \param[in] leading_components the components per region held to the sigma limit
 *  \return the measures
 */
FitMeasures
measureFit (const MorphableModel& model, const ComponentSelection& selection, const Eigen::VectorXd& coefficients,
            const Eigen::Matrix4d& similarity, const Eigen::Matrix3Xd& fitted_vertices,
            const Eigen::VectorXd& vertex_residuals, const Eigen::Matrix3Xd& scan, const IcpReport& report,
            int leading_components);

/** \brief Checks a finished fit's \a measures against \a settings. A divergence other than "unsolvable" fails no
 *  check by itself: the fit returns its best state, which the other checks judge.
 *  \param[in] measures the fit's measures
 *  \param[in] settings the limits of the checks
 *  \return the verdict, with a sentence per failed check
 */
FitPlausibility
checkFitPlausibility (const FitMeasures& measures,
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
