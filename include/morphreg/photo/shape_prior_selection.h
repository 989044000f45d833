// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file shape_prior_selection.h
 *  \brief The shape prior's weight lambda_2 chosen from the data (docs/method.md, "The shape prior"): the weight the
 *  stated landmark noise gives, scaled by the multiple that best predicts landmarks left out of the fit; where no
 *  multiple predicts them better than the mean head, a weight that keeps the fit near the mean.
 */
#include <morphreg/photo/multi_view_problem.h>
#include <morphreg/photo/photo_fit.h>

namespace morphreg
{
/** \brief Chooses lambda_2 for a MultiViewProblem.
 *
 *  The noise weight is sigma * (model mm per pixel): with rows of unit weight, the posterior mode of a fit whose
 *  image residuals are Gaussian with sigma pixels. Model error (an unseen head, hair) is not noise, so the weight is
 *  validated: the landmarks are split into kFolds runs in the order of their ids (regions of the face; a landmark
 *  marked in several photos stays in one run), each run is left out of a fit at each multiple in multiples() of the
 *  noise weight, and the multiple whose fits predict the left-out landmarks best (RMS in-image error, model mm) is
 *  chosen, unless the mean head, posed by the same data, predicts them as well (within kMinimumGain): then
 *  kNearMean times the noise weight keeps the fit near the mean head, and the choice says so. A fit of the outlines
 *  alone leaves every landmark out at once. With fewer than kMinimumLandmarks landmarks there is nothing to
 *  validate on, and kDefaultMultiple is taken.
 */
class ShapePriorSelection
{
public:
  static constexpr int kFolds = 3;                ///< groups of landmarks left out in turn
  static constexpr int kIterations = 8;           ///< Gauss-Newton iterations of each left-out fit's shape stages
  static constexpr int kMinimumLandmarks = 5;     ///< fewer: the noise weight times kDefaultMultiple, not validated
  static constexpr double kDefaultMultiple = 3.0; ///< the multiple taken without validation
  static constexpr double kNearMean = 100.0;      ///< the multiple that keeps a fit near the mean head
  /** The fraction by which the best multiple's left-out error must lie below the mean head's for the photos to
   *  predict better than it (a fit that only nears the mean head does not). */
  static constexpr double kMinimumGain = 0.01;

  /** \brief The multiples of the noise weight tried.
   *  \return 1, 3, 10 and 30
   */
  static const std::vector<double>&
  multiples ();

  /** \brief Throws InvalidInputError unless \a landmark_noise is finite and > 0.
   *  \param[in] landmark_noise the landmarks' noise in pixels (one standard deviation per coordinate)
   */
  explicit ShapePriorSelection (double landmark_noise);

  /** \brief Chooses lambda_2 for \a problem fitted with \a rows (its cameras estimated); the problem's prior weight
   *  is left at the choice.
   *  \param[in,out] problem the problem
   *  \param[in] rows what the fit uses
   *  \return the weight, the candidates' left-out errors and the mean head's
   */
  ShapePriorChoice
  choose (MultiViewProblem& problem, PhotoRows rows) const;

private:
  /** The left-out flags of each fold. */
  std::vector<std::vector<bool>>
  folds (const MultiViewProblem& problem, PhotoRows rows) const;

  double noise_;
};
} // namespace morphreg
