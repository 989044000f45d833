// SPDX-License-Identifier: BSD-3-Clause
#pragma once
#include <morphreg/registration/kernels/huber_kernel.h>

#include <memory>

namespace morphreg
{
/** \brief The Cauchy (Lorentzian) kernel ("cauchy"): weight 1 / (1 + (d / c)^2). Softly redescending: far
 *  correspondences keep a small pull that falls as 1/d^2; a graduated fit starts with Huber's kernel. */
class CauchyKernel : public RobustKernel
{
public:
  using RobustKernel::RobustKernel;

  std::string
  name () const override
  {
    return "cauchy";
  }

  double
  weightAt (double u) const override
  {
    return 1.0 / (1.0 + u * u);
  }

  double
  tuningConstant () const override
  {
    return 2.3849;
  }

  ConstPtr
  graduatedStart () const override
  {
    return std::make_shared<HuberKernel> (getScale ());
  }
};
} // namespace morphreg
