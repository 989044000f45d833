// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/order_statistics.h>
#include <morphreg/registration/robust_kernels.h>

#include <algorithm>

namespace morphreg
{
double
robustWeight (RobustLoss loss, double distance, double width)
{
  switch (loss) {
  case RobustLoss::huber:
    return distance <= width ? 1.0 : width / distance;
  case RobustLoss::tukey: {
    if (distance >= width)
      return 0.0;
    const double u = 1.0 - (distance / width) * (distance / width);
    return u * u;
  }
  case RobustLoss::none:
    break;
  }
  return 1.0;
}

double
robustKernelWidth (RobustLoss loss, const std::vector<double>& distances, double scale)
{
  if (loss == RobustLoss::none || scale > 0.0)
    return scale;
  const double sigma = distances.empty () ? 0.0 : 1.4826 * median (distances);
  return (loss == RobustLoss::huber ? 1.345 : 4.685) * std::max (sigma, 1e-6);
}
} // namespace morphreg
