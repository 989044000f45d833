// SPDX-License-Identifier: BSD-3-Clause
#pragma once
#include <morphreg/registration/robust_kernel.h>

namespace morphreg
{
/** \brief Huber's kernel ("huber"): weight min(1, c / d). Convex: far correspondences keep a pull that falls as 1/d. */
class HuberKernel : public RobustKernel
{
public:
  using RobustKernel::RobustKernel;

  std::string
  name () const override
  {
    return "huber";
  }

  double
  weightAt (double u) const override
  {
    return u <= 1.0 ? 1.0 : 1.0 / u;
  }

  double
  tuningConstant () const override
  {
    return 1.345;
  }
};
} // namespace morphreg
