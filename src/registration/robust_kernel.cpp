// SPDX-License-Identifier: BSD-3-Clause
// The kernels by name: the one place a new kernel is registered.
#include <morphreg/common/error.h>
#include <morphreg/common/order_statistics.h>
#include <morphreg/registration/kernels/cauchy_kernel.h>
#include <morphreg/registration/kernels/geman_mcclure_kernel.h>
#include <morphreg/registration/kernels/huber_kernel.h>
#include <morphreg/registration/kernels/least_squares_kernel.h>
#include <morphreg/registration/kernels/tukey_kernel.h>
#include <morphreg/registration/robust_kernel.h>

#include <algorithm>
#include <functional>
#include <utility>

namespace morphreg
{
namespace
{
using KernelMaker = std::function<RobustKernel::Ptr (double scale)>;

template <typename Kernel>
std::pair<std::string, KernelMaker>
entry ()
{
  const KernelMaker make = [] (double scale) { return std::make_shared<Kernel> (scale); };
  return {make (0.0)->name (), make};
}

/** Every kernel, in the order settings list them. */
const std::vector<std::pair<std::string, KernelMaker>>&
registry ()
{
  static const std::vector<std::pair<std::string, KernelMaker>> kernels = {
      entry<LeastSquaresKernel> (), entry<HuberKernel> (), entry<TukeyKernel> (), entry<CauchyKernel> (),
      entry<GemanMcClureKernel> ()};
  return kernels;
}
} // namespace

RobustKernel::RobustKernel (double scale) : scale_ (scale > 0.0 ? scale : 0.0) {}

double
RobustKernel::width (const std::vector<double>& distances) const
{
  if (scale_ > 0.0)
    return scale_;
  const double sigma = distances.empty () ? 0.0 : 1.4826 * median (distances);
  return tuningConstant () * std::max (sigma, 1e-6);
}

const std::vector<std::string>&
robustKernelNames ()
{
  static const std::vector<std::string> names = [] {
    std::vector<std::string> listed;
    for (const auto& kernel : registry ())
      listed.push_back (kernel.first);
    return listed;
  }();
  return names;
}

RobustKernel::Ptr
makeRobustKernel (const std::string& name, double scale)
{
  for (const auto& [known, make] : registry ())
    if (known == name)
      return make (scale);
  std::string listed;
  for (const std::string& known : robustKernelNames ())
    listed += (listed.empty () ? "" : ", ") + known;
  throw InvalidInputError ("robust kernel \"" + name + "\" is none of " + listed);
}

} // namespace morphreg
