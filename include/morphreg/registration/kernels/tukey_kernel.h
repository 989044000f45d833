// SPDX-License-Identifier: BSD-3-Clause
#pragma once
#include <morphreg/registration/kernels/huber_kernel.h>

#include <memory>

namespace morphreg
{
/** \brief Tukey's biweight ("tukey"): weight (1 - (d / c)^2)^2 inside c, 0 beyond. Redescending: correspondences
 *  beyond c (outliers, other objects) weigh nothing; a graduated fit starts with Huber's kernel. */
class TukeyKernel : public RobustKernel
{
public:
  using RobustKernel::RobustKernel;

  std::string
  name () const override
  {
    return "tukey";
  }

  double
  weightAt (double u) const override
  {
    if (u >= 1.0)
      return 0.0;
    const double v = 1.0 - u * u;
    return v * v;
  }

  double
  tuningConstant () const override
  {
    return 4.685;
  }

  ConstPtr
  graduatedStart () const override
  {
    return std::make_shared<HuberKernel> (getScale ());
  }
};
} // namespace morphreg
