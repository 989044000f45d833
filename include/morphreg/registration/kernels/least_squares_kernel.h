// SPDX-License-Identifier: BSD-3-Clause
#pragma once
#include <morphreg/registration/robust_kernel.h>

namespace morphreg
{
/** \brief Plain least squares ("none"): every correspondence weighs 1, whatever its distance. */
class LeastSquaresKernel : public RobustKernel
{
public:
  using RobustKernel::RobustKernel;

  std::string
  name () const override
  {
    return "none";
  }

  double
  weightAt (double) const override
  {
    return 1.0;
  }

  double
  tuningConstant () const override
  {
    return 1.0; // the width does not matter
  }
};
} // namespace morphreg
