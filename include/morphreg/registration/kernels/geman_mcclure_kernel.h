// SPDX-License-Identifier: BSD-3-Clause
#pragma once
#include <morphreg/registration/kernels/huber_kernel.h>

#include <memory>

namespace morphreg
{
/** \brief The Geman-McClure kernel ("geman_mcclure"): weight 1 / (1 + (d / c)^2)^2. Redescending faster than
 *  Cauchy's (far correspondences fall as 1/d^4); a graduated fit starts with Huber's kernel. */
class GemanMcClureKernel : public RobustKernel
{
public:
  using RobustKernel::RobustKernel;

  std::string
  name () const override
  {
    return "geman_mcclure";
  }

  double
  weightAt (double u) const override
  {
    const double v = 1.0 + u * u;
    return 1.0 / (v * v);
  }

  double
  tuningConstant () const override
  {
    return 3.7874; // 95 % efficiency under Gaussian residuals
  }

  ConstPtr
  graduatedStart () const override
  {
    return std::make_shared<HuberKernel> (getScale ());
  }
};
} // namespace morphreg
