// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/model/coefficient_units.h>

namespace morphreg
{
Eigen::VectorXd
coefficientsInStandardDeviations (const MorphableModel& model, const Eigen::VectorXd& coefficients_mm,
                                  const ComponentSelection& selection)
{
  model.requireCompatible (selection, &coefficients_mm, "coefficientsInStandardDeviations");
  return coefficients_mm.cwiseProduct (model.lambdaDiagonal (selection, ShapePrior::inverse_std_dev));
}

Eigen::VectorXd
coefficientsInMillimetres (const MorphableModel& model, const Eigen::VectorXd& coefficients_sd,
                           const ComponentSelection& selection)
{
  model.requireCompatible (selection, &coefficients_sd, "coefficientsInMillimetres");
  return coefficients_sd.cwiseQuotient (model.lambdaDiagonal (selection, ShapePrior::inverse_std_dev));
}
} // namespace morphreg
