// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file coefficient_units.h
 *  \brief Shape coefficients in the two units people use: lengths (mm along the model's orthonormal components,
 *  what MorphableModel::generate takes) and prior standard deviations (statismo, scalismo, BFM and eos: a
 *  coefficient of 1 is one standard deviation of the population along its component). See docs/coefficients.md.
 */
#include <morphreg/model/component_selection.h>
#include <morphreg/model/morphable_model.h>

#include <Eigen/Core>

namespace morphreg
{
/** \brief What the reports' "coefficients" hold (their "coefficients_unit"); "coefficients_mm" holds the lengths. */
inline constexpr const char* kCoefficientsUnit = "prior standard deviations";

/** \brief The coefficients \a coefficients_mm of \a selection in prior standard deviations: m_k / sqrt(variance_k)
 *  (a component of zero variance is taken as 1e-12 of the largest, as in the shape prior). Throws
 *  InvalidInputError when the sizes disagree.
 *  \param[in] model the model whose variances set the scale
 *  \param[in] coefficients_mm stacked coefficients in mm (like selection)
 *  \param[in] selection the components they belong to
 *  \return the coefficients in standard deviations
 */
Eigen::VectorXd
coefficientsInStandardDeviations (const MorphableModel& model, const Eigen::VectorXd& coefficients_mm,
                                  const ComponentSelection& selection);

/** \brief The inverse of coefficientsInStandardDeviations: sd_k * sqrt(variance_k), lengths in mm that
 *  MorphableModel::generate takes. Throws InvalidInputError when the sizes disagree.
 *  \param[in] model the model whose variances set the scale
 *  \param[in] coefficients_sd stacked coefficients in prior standard deviations (like selection)
 *  \param[in] selection the components they belong to
 *  \return the coefficients in mm
 */
Eigen::VectorXd
coefficientsInMillimetres (const MorphableModel& model, const Eigen::VectorXd& coefficients_sd,
                           const ComponentSelection& selection);
} // namespace morphreg
